#include "sim/lane_measures.h"

#include <algorithm>

#include "sim/body_frame.h"
#include "sim/trace.h"
#include "simd/isa.h"

namespace hexgait {
namespace {

// W values of T as a GCC vector (the type must depend on T for GCC to apply a size that
// depends on W).
template <class T, int W>
struct VectorOf {
  typedef T type __attribute__((vector_size(sizeof(T) * W)));
};

// BodyFrame's operations on Block lanes of doubles. Min is std::fmin's choice for numbers (the
// first argument unless the second is smaller): the lanes it is asked about passed the
// divergence test, so none is NaN.
template <int Block>
struct LaneFrameOps {
  using V = typename VectorOf<double, Block>::type;
  [[gnu::always_inline]] static V Splat(double value) { return value - V{}; }
  [[gnu::always_inline]] static V Sqrt(V v) {
    V r;
    for (int l = 0; l < Block; ++l) r[l] = __builtin_sqrt(v[l]);
    return r;
  }
  [[gnu::always_inline]] static V SelectPositive(V s, V a, V b) { return s > 0 ? a : b; }
  [[gnu::always_inline]] static V Min(V a, V b) { return b < a ? b : a; }
};

// MeasureLanes in blocks of Block lanes, inlined whole into a function of one instruction set
// (below): its vectors, BodyFrame's and BoundsTest's code are then compiled for that set. The
// results do not depend on it: every operation is a correctly rounded IEEE one, without FMA.
template <class T, int Block>
[[gnu::always_inline]] inline void MeasureBlocks(const CreatureModel& model,
                                                 const BatchStateT<T>& batch, double limit,
                                                 int first_lane, int lane_count,
                                                 std::span<BodyMeasures> body,
                                                 std::span<char> in_bounds) {
  using Ops = LaneFrameOps<Block>;
  using V = typename Ops::V;
  const int lanes = batch.lanes;
  const int n = model.num_particles();
  const int end = first_lane + lane_count;
  for (int first = first_lane; first < end; first += Block) {
    const int count = std::min(Block, end - first);
    // Particle i's component c in lanes first.., widened; a narrower batch repeats its last.
    auto load = [&](int i, int c) __attribute__((always_inline)) {
      const T* p = batch.state.data() + (static_cast<size_t>(i) * 6 + c) * lanes + first;
      if (count == Block) {
        typename VectorOf<T, Block>::type v;
        __builtin_memcpy(&v, p, sizeof v);
        return __builtin_convertvector(v, V);
      }
      V v{};
      for (int l = 0; l < Block; ++l) v[l] = static_cast<double>(p[std::min(l, count - 1)]);
      return v;
    };
    auto position = [&](int i) __attribute__((always_inline)) {
      return Point<V>{load(i, 0), load(i, 1), load(i, 2)};
    };
    BoundsTest<V> bounds(limit);
    for (int i = 0; i < n; ++i) {
      bounds.Add(load(i, 0), load(i, 1), load(i, 2), load(i, 3), load(i, 4), load(i, 5));
    }
    const auto in = bounds.Passes();
    Point<V> forward, left, up;
    BodyFrame<Ops>::Axes(model, position, forward, left, up);
    const V lowest = BodyFrame<Ops>::Lowest(model, position);
    for (int l = 0; l < count; ++l) {
      const int lane = first + l;
      in_bounds[lane] = in[l] != 0;
      body[lane] = {lowest[l], up.z[l], FeetOnGroundAt(model, [&](int i) {
                      return static_cast<double>(batch.at(i, 2, lane));
                    })};
    }
  }
}

// Two doubles: the baseline instruction set's vector (SSE2), on which GCC keeps comparisons
// and selections in registers (wider vectors it splits, and their comparisons into branches).
template <class T>
void MeasureBaseline(const CreatureModel& model, const BatchStateT<T>& batch, double limit,
                     int first, int count, std::span<BodyMeasures> body, std::span<char> in) {
  MeasureBlocks<T, 2>(model, batch, limit, first, count, body, in);
}

// Eight: one AVX-512 register, a quarter of the instructions of SSE2's two.
template <class T>
[[gnu::target("avx512f,avx512dq,avx512vl,avx512bw")]] void MeasureAvx512(
    const CreatureModel& model, const BatchStateT<T>& batch, double limit, int first, int count,
    std::span<BodyMeasures> body, std::span<char> in) {
  MeasureBlocks<T, 8>(model, batch, limit, first, count, body, in);
}

}  // namespace

template <class T>
void MeasureLanes(const CreatureModel& model, const BatchStateT<T>& batch, double limit, int first,
                  int count, std::span<BodyMeasures> body, std::span<char> in_bounds,
                  BatchIsa isa) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  // Whole AVX-512 vectors only: a lane or two alone (a refilled batch checks its lanes one at a
  // time, each on its own clock) costs less in SSE2's.
  const int whole = isa == BatchIsa::kAvx512 ? count / 8 * 8 : 0;
  if (whole > 0) MeasureAvx512(model, batch, limit, first, whole, body, in_bounds);
  if (whole < count) {
    MeasureBaseline(model, batch, limit, first + whole, count - whole, body, in_bounds);
  }
}

template void MeasureLanes<double>(const CreatureModel&, const BatchStateT<double>&, double, int,
                                   int, std::span<BodyMeasures>, std::span<char>, BatchIsa);
template void MeasureLanes<float>(const CreatureModel&, const BatchStateT<float>&, double, int, int,
                                  std::span<BodyMeasures>, std::span<char>, BatchIsa);

}  // namespace hexgait
