#include "sim/lane_measures.h"

#include <algorithm>

#include "sim/body_frame.h"
#include "sim/trace.h"

namespace hexgait {
namespace {

// Two doubles: the baseline instruction set's vector (SSE2), on which GCC keeps comparisons
// and selections in vector registers; wider vectors it splits, and their comparisons it split
// into scalar branches.
constexpr int kMeasureBlock = 2;  // lanes measured together
typedef double LaneDoubles __attribute__((vector_size(sizeof(double) * kMeasureBlock)));

// BodyFrame's operations on kMeasureBlock lanes. Min is std::fmin's choice for numbers (the first
// argument unless the second is smaller): the lanes it is asked about passed the divergence
// test, so none is NaN.
struct LaneFrameOps {
  using V = LaneDoubles;
  static V Splat(double value) { return value - V{}; }
  static V Sqrt(V v) {
    V r;
    for (int l = 0; l < kMeasureBlock; ++l) r[l] = __builtin_sqrt(v[l]);
    return r;
  }
  static V SelectPositive(V s, V a, V b) { return s > 0 ? a : b; }
  static V Min(V a, V b) { return b < a ? b : a; }
};

}  // namespace

template <class T>
void MeasureLanes(const CreatureModel& model, const BatchStateT<T>& batch, double limit,
                  int first_lane, int lane_count, std::span<BodyMeasures> body,
                  std::span<char> in_bounds) {
  const int lanes = batch.lanes;
  const int n = model.num_particles();
  const int end = first_lane + lane_count;
  for (int first = first_lane; first < end; first += kMeasureBlock) {
    const int count = std::min(kMeasureBlock, end - first);
    // Particle i's component c in lanes first.., widened; a narrower batch repeats its last.
    auto load = [&](int i, int c) {
      const T* p = batch.state.data() + (static_cast<size_t>(i) * 6 + c) * lanes + first;
      if (count == kMeasureBlock) {
        typedef T Block __attribute__((vector_size(sizeof(T) * kMeasureBlock)));
        Block v;
        __builtin_memcpy(&v, p, sizeof v);
        return __builtin_convertvector(v, LaneDoubles);
      }
      LaneDoubles v;
      for (int l = 0; l < kMeasureBlock; ++l) v[l] = static_cast<double>(p[std::min(l, count - 1)]);
      return v;
    };
    auto position = [&](int i) { return Point<LaneDoubles>{load(i, 0), load(i, 1), load(i, 2)}; };
    BoundsTest<LaneDoubles> bounds(limit);
    for (int i = 0; i < n; ++i) {
      bounds.Add(load(i, 0), load(i, 1), load(i, 2), load(i, 3), load(i, 4), load(i, 5));
    }
    const auto in = bounds.Passes();
    Point<LaneDoubles> forward, left, up;
    BodyFrame<LaneFrameOps>::Axes(model, position, forward, left, up);
    const LaneDoubles lowest = BodyFrame<LaneFrameOps>::Lowest(model, position);
    for (int l = 0; l < count; ++l) {
      const int lane = first + l;
      in_bounds[lane] = in[l] != 0;
      body[lane] = {lowest[l], up.z[l], FeetOnGroundAt(model, [&](int i) {
                      return static_cast<double>(batch.at(i, 2, lane));
                    })};
    }
  }
}

template void MeasureLanes<double>(const CreatureModel&, const BatchStateT<double>&, double, int,
                                   int, std::span<BodyMeasures>, std::span<char>);
template void MeasureLanes<float>(const CreatureModel&, const BatchStateT<float>&, double, int, int,
                                  std::span<BodyMeasures>, std::span<char>);

}  // namespace hexgait
