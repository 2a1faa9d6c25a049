// The batched explicit-Euler kernel's source, included by one translation unit per
// instruction set (batch_kernel_generic.cc, _avx2.cc, _avx512.cc), each compiled with its own
// -m flags. Everything here has internal linkage and calls only compiler builtins: an inline
// function with external linkage compiled for AVX-512 could otherwise be picked by the linker
// for every caller and fault on a CPU without it.
//
// The physics is sim/physics_terms.h's, the same functions the scalar path (sim/forces.cc,
// sim/integrator.cc) calls, with spring forces summed onto each particle in the scalar path's
// order: that is what makes a lane bit-identical to it.
#include <cstddef>
#include <type_traits>
#include <utility>

#include "motor/rest_transition.h"
#include "sim/batch_kernel_args.h"
#include "sim/physics_terms.h"

#ifndef HEXGAIT_BATCH_NATIVE_LANES
#error "define HEXGAIT_BATCH_NATIVE_LANES (doubles per vector register) before including"
#endif

// Clang, in the sanitizer build, leaves the spring pass's lambdas out of line, and the pipeline's
// SpringHead copies then go through AddressSanitizer's memcpy and its region checks: a third of
// a sanitized refill test's samples (docs/ci_timings.md, f36c900). GCC inlines them unasked, and
// forcing it there changes its code, so only Clang is told.
#ifdef __clang__
#define HEXGAIT_KERNEL_INLINE __attribute__((always_inline))
#else
#define HEXGAIT_KERNEL_INLINE
#endif

namespace {

// W values of T (double or float), and the matching lane mask (all ones or all zeros per
// lane), as GCC vector extensions: arithmetic on them is element-wise and lowers to the widest
// vectors the translation unit's instruction set has (a V of 16 doubles is two AVX-512
// registers, of 16 floats one).
template <class T>
struct MaskElement;
template <>
struct MaskElement<double> {
  using type = long long;
};
template <>
struct MaskElement<float> {
  using type = int;
};

template <class T, int W>
struct Lanes {
  typedef T V __attribute__((vector_size(sizeof(T) * W)));
  typedef typename MaskElement<T>::type M __attribute__((vector_size(sizeof(T) * W)));
};

template <class T, int W>
inline typename Lanes<T, W>::V Load(const T* p) {
  typename Lanes<T, W>::V v;
  __builtin_memcpy(&v, p, sizeof v);  // unaligned load: a lane group is 64-byte aligned at best
  return v;
}
template <class T, int W>
inline void Store(T* p, typename Lanes<T, W>::V v) {
  __builtin_memcpy(p, &v, sizeof v);
}
// Every lane `value`, exactly (x - +0 is x for every x, -0 included): GCC lowers vector minus
// scalar to one broadcast, where a per-lane loop became a masked insert per lane.
template <class T, int W>
inline typename Lanes<T, W>::V Broadcast(T value) {
  return value - typename Lanes<T, W>::V{};
}
// Whether any bit of `v` (a vector of integers) is set: its halves ORed in registers until one
// word is left, where testing each lane became an extract and a branch per lane.
template <class V, std::size_t... I>
inline auto OrHalves(V v, std::index_sequence<I...>) {
  return __builtin_shufflevector(v, v, I...) | __builtin_shufflevector(v, v, (I + sizeof...(I))...);
}
template <class V>
inline bool AnyBit(V v) {
  constexpr std::size_t kCount = sizeof(V) / sizeof(v[0]);
  if constexpr (kCount == 1 || sizeof(V) <= 8) {
    std::conditional_t<sizeof(V) == 8, unsigned long long, unsigned> word;
    __builtin_memcpy(&word, &v, sizeof word);
    return word != 0;
  } else {
    return AnyBit(OrHalves(v, std::make_index_sequence<kCount / 2>()));
  }
}
template <class T, int W>
inline bool AnyLane(typename Lanes<T, W>::M mask) {
  return AnyBit(mask);
}
// Correctly rounded, like std::sqrt: GCC turns the loop into vector square roots.
template <class T, int W>
inline typename Lanes<T, W>::V Sqrt(typename Lanes<T, W>::V v) {
  typename Lanes<T, W>::V r;
  for (int l = 0; l < W; ++l) {
    if constexpr (sizeof(T) == 4) {
      r[l] = __builtin_sqrtf(v[l]);
    } else {
      r[l] = __builtin_sqrt(v[l]);
    }
  }
  return r;
}
// Per lane: mask ? a : b, exactly (bitwise, so signed zeros and NaNs pass through unchanged).
template <class T, int W>
inline typename Lanes<T, W>::V Select(typename Lanes<T, W>::M mask, typename Lanes<T, W>::V a,
                                      typename Lanes<T, W>::V b) {
  using M = typename Lanes<T, W>::M;
  using V = typename Lanes<T, W>::V;
  return reinterpret_cast<V>((reinterpret_cast<M>(a) & mask) | (reinterpret_cast<M>(b) & ~mask));
}

// Physics<Ops> (sim/physics_terms.h) on blocks of N lanes of T.
template <class Scalar, int N>
struct LaneOps {
  using T = Scalar;
  using V = typename Lanes<T, N>::V;
  using M = typename Lanes<T, N>::M;
  static V Splat(T value) { return Broadcast<T, N>(value); }
  static V Sqrt(V v) { return ::Sqrt<T, N>(v); }
  static M GreaterEqual(V a, V b) { return a >= b; }
  static M LessEqual(V a, V b) { return a <= b; }
  static M NeitherOf(M a, M b) { return ~a & ~b; }
  static bool All(M m) { return !AnyLane<T, N>(~m); }
  static V Select(M m, V a, V b) { return ::Select<T, N>(m, a, b); }
};

// Adds a particle's spring forces to (fx, fy, fz) in spring order: added at a spring's a end,
// subtracted at its b end. `sf` points at lane block b of the first spring's force. With one
// lane, the sums are plain T: GCC keeps one-element vectors carried around a loop in memory.
template <class T, int W, int N>
inline void SumSpringForces(const T* __restrict sf, const int* e, const int* end,
                            typename Lanes<T, N>::V& fx, typename Lanes<T, N>::V& fy,
                            typename Lanes<T, N>::V& fz) {
  enum { FX = 0, FY = W, FZ = 2 * W };
  using Sum = std::conditional_t<N == 1, T, typename Lanes<T, N>::V>;
  Sum x, y, z;
  if constexpr (N == 1) {
    x = fx[0], y = fy[0], z = fz[0];
  } else {
    x = fx, y = fy, z = fz;
  }
  for (; e != end; ++e) {
    const T* f = sf + (*e >> 1);
    Sum gx, gy, gz;
    __builtin_memcpy(&gx, f + FX, sizeof gx);
    __builtin_memcpy(&gy, f + FY, sizeof gy);
    __builtin_memcpy(&gz, f + FZ, sizeof gz);
    if (*e & 1) {
      x = x - gx, y = y - gy, z = z - gz;
    } else {
      x = x + gx, y = y + gy, z = z + gz;
    }
  }
  if constexpr (N == 1) {
    fx[0] = x, fy[0] = y, fz[0] = z;
  } else {
    fx = x, fy = y, fz = z;
  }
}

// A spring block's differences, length and inverse length: what the spring pass carries from one
// block to the next.
template <class V>
struct SpringHead {
  V dx, dy, dz, length, inv;
};

// One explicit Euler step of W lanes, processed as blocks of N lanes (N: the widest vector
// of T the translation unit's instruction set has, or W if smaller).
//
// Two passes, as in the scalar kernel. First every spring's force, stored; then, particle by
// particle, the sum of its springs' forces in spring order (the order the scalar kernel adds
// them in), the ground force and the Euler update, all in registers: a particle's force is
// never stored, and no force update waits on the store of the one before.
//
// The spring pass is software-pipelined: block j + 2's differences, square root and division
// are issued before block j's force is finished. That latency is most of a block's, and the
// core's scheduler holds too few blocks' operations to overlap it unaided (docs/speed.md). The
// order of work changes, not any spring's operations: the bits are the scalar path's.
template <class T, int W, int N>
void StepLanes(const hexgait::BatchKernelArgsT<T>& a) {
  static_assert(W % N == 0, "lanes must be a multiple of the block width");
  using Ops = LaneOps<T, N>;
  using V = typename Ops::V;
  const int n = a.num_particles;
  const int ns = a.num_springs;
  const int* __restrict sa = a.spring_a;
  const int* __restrict sb = a.spring_b;
  const T* __restrict k = a.stiffness;
  const T* __restrict c = a.damping;
  const T* __restrict mass = a.mass;
  const T* __restrict inv_mass = a.inv_mass;
  T* __restrict p = a.state;          // particle i: x, y, z, vx, vy, vz at (6 i + 0..5) W
  T* __restrict sf = a.spring_force;  // spring s: fx, fy, fz at (3 s + 0..2) W
  const T* __restrict rest = a.rest_length;
  const int* __restrict incident_start = a.incident_start;
  const int* __restrict incident = a.incident;
  const T g = a.gravity;
  enum { X = 0, Y = W, Z = 2 * W, VX = 3 * W, VY = 4 * W, VZ = 5 * W };  // offsets in a block
  enum { FX = 0, FY = W, FZ = 2 * W };
  enum { kBlocks = W / N };

  // Spring block j (spring j / kBlocks, lanes from (j % kBlocks) N): its differences, length
  // and inverse length...
  auto head = [&](int j, SpringHead<V>& h) HEXGAIT_KERNEL_INLINE {
    const int s = j / kBlocks, b = (j % kBlocks) * N;
    const T* pa = p + 6 * W * sa[s] + b;
    const T* pb = p + 6 * W * sb[s] + b;
    h.dx = Load<T, N>(pb + X) - Load<T, N>(pa + X);
    h.dy = Load<T, N>(pb + Y) - Load<T, N>(pa + Y);
    h.dz = Load<T, N>(pb + Z) - Load<T, N>(pa + Z);
    hexgait::Physics<Ops>::SpringLength(h.dx, h.dy, h.dz, h.length, h.inv);
  };
  // ...and its force from them, stored.
  auto tail = [&](int j, const SpringHead<V>& h) HEXGAIT_KERNEL_INLINE {
    const int s = j / kBlocks, b = (j % kBlocks) * N;
    const T* pa = p + 6 * W * sa[s] + b;
    const T* pb = p + 6 * W * sb[s] + b;
    const V dvx = Load<T, N>(pb + VX) - Load<T, N>(pa + VX);
    const V dvy = Load<T, N>(pb + VY) - Load<T, N>(pa + VY);
    const V dvz = Load<T, N>(pb + VZ) - Load<T, N>(pa + VZ);
    V fx, fy, fz;
    hexgait::Physics<Ops>::SpringForce(h.dx, h.dy, h.dz, dvx, dvy, dvz, h.length, h.inv,
                                       Ops::Splat(k[s]), Ops::Splat(c[s]),
                                       Load<T, N>(rest + s * W + b), fx, fy, fz);
    T* f = sf + 3 * W * s + b;
    Store<T, N>(f + FX, fx);
    Store<T, N>(f + FY, fy);
    Store<T, N>(f + FZ, fz);
  };
  const int num_blocks = ns * kBlocks;
  if (num_blocks > 1) {
    SpringHead<V> h0, h1, h2;
    head(0, h0);
    head(1, h1);
    for (int j = 0; j + 2 < num_blocks; ++j) {
      head(j + 2, h2);
      tail(j, h0);
      h0 = h1;
      h1 = h2;
    }
    tail(num_blocks - 2, h0);
    tail(num_blocks - 1, h1);
  } else if (num_blocks == 1) {
    SpringHead<V> h0;
    head(0, h0);
    tail(0, h0);
  }

  const hexgait::GroundConstants<T> ground = {a.ground_stiffness, a.ground_damping, a.friction,
                                              a.slip_velocity2};
  const V dt = Ops::Splat(a.dt);
  const V zero = Ops::Splat(T(0));
  for (int i = 0; i < n; ++i) {
    const V weight = Ops::Splat(-mass[i] * g);
    const V h = Ops::Splat(a.dt * inv_mass[i]);
    const int first = incident_start[i], last = incident_start[i + 1];
    for (int b = 0; b < W; b += N) {
      V fx = zero, fy = zero, fz = weight;
      SumSpringForces<T, W, N>(sf + b, incident + first, incident + last, fx, fy, fz);

      // Ground, then explicit Euler, in registers.
      T* pi = p + 6 * W * i + b;
      V x = Load<T, N>(pi + X), y = Load<T, N>(pi + Y), z = Load<T, N>(pi + Z);
      V vx = Load<T, N>(pi + VX), vy = Load<T, N>(pi + VY), vz = Load<T, N>(pi + VZ);
      hexgait::Physics<Ops>::Ground(ground, z, vx, vy, vz, fx, fy, fz);
      hexgait::Physics<Ops>::Euler(dt, h, fx, fy, fz, x, y, z, vx, vy, vz);
      Store<T, N>(pi + X, x);
      Store<T, N>(pi + Y, y);
      Store<T, N>(pi + Z, z);
      Store<T, N>(pi + VX, vx);
      Store<T, N>(pi + VY, vy);
      Store<T, N>(pi + VZ, vz);
    }
  }
}

// Values of T per vector register in this translation unit.
template <class T>
constexpr int kNative = HEXGAIT_BATCH_NATIVE_LANES* static_cast<int>(sizeof(double) / sizeof(T));

template <class T>
constexpr int Block(int lanes) {
  return lanes < kNative<T> ? lanes : kNative<T>;
}

// The vector registers this translation unit's instruction set names.
#ifdef __AVX512F__
constexpr int kVectorRegisters = 32;
#else
constexpr int kVectorRegisters = 16;
#endif

// Independent chains of multiplies in the peak loop, and as many of adds: up to 8, enough to
// keep two pipes of each busy through their latency, and few enough to stay in registers with m
// and a and two to spare: 8 + 8 chains on SSE2 and AVX2 left three in memory and the loop timed
// store-to-load forwarding instead of arithmetic (docs/speed.md, "On a Zen 3").
constexpr int kPeakChains = (kVectorRegisters - 4) / 2 < 8 ? (kVectorRegisters - 4) / 2 : 8;

// The machine's peak for the kernel's kind of arithmetic: kPeakChains independent chains of
// vector multiplies and as many of adds (no fused multiply-add: the project compiles with
// -ffp-contract=off, so the kernel cannot use it either). Returns a value that depends on every
// chain, so nothing is optimised away; performs 2 * kPeakChains * kNative<T> flops per iteration.
template <class T>
double PeakLoop(long long iterations, T m, T a) {
  constexpr int N = kNative<T>;
  using V = typename Lanes<T, N>::V;
  V p[kPeakChains], q[kPeakChains];
  for (int j = 0; j < kPeakChains; ++j) {
    p[j] = Broadcast<T, N>(T(1) + T(j));
    q[j] = Broadcast<T, N>(T(2) + T(j));
  }
  for (long long it = 0; it < iterations; ++it) {
    for (int j = 0; j < kPeakChains; ++j) {
      p[j] = p[j] * m;
      q[j] = q[j] + a;
    }
  }
  double sum = 0;
  for (int j = 0; j < kPeakChains; ++j) {
    for (int l = 0; l < N; ++l) sum += static_cast<double>(p[j][l] + q[j][l]);
  }
  return sum;
}

// The square-root-and-divide floor: 8 independent chains of x <- 1 / sqrt(x) on full vectors
// (x converges to 1, so no denormals). Performs 8 square roots and 8 divisions of kNative<T>
// lanes per iteration.
template <class T>
double SqrtDivLoop(long long iterations, T seed) {
  constexpr int N = kNative<T>;
  using V = typename Lanes<T, N>::V;
  V p[8];
  for (int j = 0; j < 8; ++j) p[j] = Broadcast<T, N>(seed + T(j));
  for (long long it = 0; it < iterations; ++it) {
    for (int j = 0; j < 8; ++j) p[j] = T(1) / Sqrt<T, N>(p[j]);
  }
  double sum = 0;
  for (int j = 0; j < 8; ++j) {
    for (int l = 0; l < N; ++l) sum += static_cast<double>(p[j][l]);
  }
  return sum;
}

// Interpolation as the scalar MotorController::Move computes it, one vector of lanes at a time.
template <class T>
void InterpolateLanes(const double* __restrict from, const double* __restrict change, double f,
                      T* __restrict out, int count) {
  for (int e = 0; e < count; ++e) out[e] = hexgait::Interpolate<T>(from[e], f, change[e]);
}

template <class T>
void InterpolateSpan(const double* __restrict from, const double* __restrict change,
                     const double* __restrict fraction, T* __restrict out, int count) {
  for (int e = 0; e < count; ++e) out[e] = hexgait::Interpolate<T>(from[e], fraction[e], change[e]);
}

void TransitionFractions(const double* __restrict start, double step, double steps,
                         double* __restrict fraction, int count) {
  for (int e = 0; e < count; ++e) {
    // Integers: exact, as (step - start + 1).
    fraction[e] = hexgait::StepFraction(step - start[e] + 1, steps);
  }
}

// LegMoveFnT with the lane count fixed at compile time (L > 0) or read from the arguments (0):
// the loops over a spring's lanes then compile to whole vectors without a remainder.
template <int L, class T>
void MoveLegsWith(const hexgait::LegMoveArgs& a, T* __restrict out) {
  const int lanes = L > 0 ? L : a.lanes;
  double* __restrict fraction = a.fraction;
  TransitionFractions(a.start, a.step, a.steps, fraction, a.legs * lanes);
  const double* __restrict from = a.from;
  const double* __restrict change = a.change;
  for (int k = 0; k < a.count; ++k) {
    const std::size_t e = static_cast<std::size_t>(a.springs[k]) * lanes;
    const double* __restrict f = fraction + static_cast<std::size_t>(a.leg_of[k]) * lanes;
    for (int l = 0; l < lanes; ++l) {
      out[e + l] = hexgait::Interpolate<T>(from[e + l], f[l], change[e + l]);
    }
  }
}

template <class T>
void MoveLegs(const hexgait::LegMoveArgs& a, T* out) {
  switch (a.lanes) {
    case 16:
      return MoveLegsWith<16>(a, out);
    case 8:
      return MoveLegsWith<8>(a, out);
    default:
      return MoveLegsWith<0>(a, out);
  }
}

// The tables a translation unit exports: index j holds the kernel for kBatchLaneCounts[j].
template <class T>
constexpr hexgait::BatchStepFnT<T> kStepTable[] = {
    StepLanes<T, 1, Block<T>(1)>, StepLanes<T, 2, Block<T>(2)>, StepLanes<T, 4, Block<T>(4)>,
    StepLanes<T, 8, Block<T>(8)>, StepLanes<T, 16, Block<T>(16)>};

constexpr hexgait::BatchIsaKernels kKernels = {
    .vector_registers = kVectorRegisters,
    .step = kStepTable<double>,
    .step_float = kStepTable<float>,
    .interpolate = InterpolateLanes<double>,
    .interpolate_float = InterpolateLanes<float>,
    .interpolate_span = InterpolateSpan<double>,
    .interpolate_span_float = InterpolateSpan<float>,
    .transition_fractions = TransitionFractions,
    .move_legs = MoveLegs<double>,
    .move_legs_float = MoveLegs<float>,
    .peak_loop = PeakLoop<double>,
    .peak_loop_float = PeakLoop<float>,
    .peak_loop_chains = kPeakChains,
    .sqrt_div_loop = SqrtDivLoop<double>,
    .sqrt_div_loop_float = SqrtDivLoop<float>,
};

}  // namespace
