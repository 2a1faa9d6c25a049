// The batched explicit-Euler kernel's source, included by one translation unit per
// instruction set (batch_kernel_generic.cc, _avx2.cc, _avx512.cc), each compiled with its own
// -m flags. Everything here has internal linkage and calls only compiler builtins: an inline
// function with external linkage compiled for AVX-512 could otherwise be picked by the linker
// for every caller and fault on a CPU without it.
//
// Per lane, the operations and their
// order are exactly those of ComputeForces and EulerStepper::Step (sim/forces.cc,
// sim/integrator.cc): that is what makes a lane bit-identical to the scalar path.
#include "sim/batch_kernel_args.h"

#ifndef HEXGAIT_BATCH_NATIVE_LANES
#error "define HEXGAIT_BATCH_NATIVE_LANES (doubles per vector register) before including"
#endif

namespace {

// W doubles, and the matching lane mask (all ones or all zeros per lane), as GCC vector
// extensions: arithmetic on them is element-wise and lowers to the widest vectors the
// translation unit's instruction set has (a V of 16 doubles is two AVX-512 registers).
template <int W>
struct Lanes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long long M __attribute__((vector_size(8 * W)));
};

template <int W>
inline typename Lanes<W>::V Load(const double* p) {
  typename Lanes<W>::V v;
  __builtin_memcpy(&v, p, sizeof v);  // unaligned load: a lane group is 64-byte aligned at best
  return v;
}
template <int W>
inline void Store(double* p, typename Lanes<W>::V v) {
  __builtin_memcpy(p, &v, sizeof v);
}
template <int W>
inline typename Lanes<W>::V Broadcast(double value) {
  typename Lanes<W>::V v;
  for (int l = 0; l < W; ++l) v[l] = value;
  return v;
}
// Correctly rounded, like std::sqrt: GCC turns the loop into vector square roots.
template <int W>
inline typename Lanes<W>::V Sqrt(typename Lanes<W>::V v) {
  typename Lanes<W>::V r;
  for (int l = 0; l < W; ++l) r[l] = __builtin_sqrt(v[l]);
  return r;
}
// Per lane: mask ? a : b, exactly (bitwise, so signed zeros and NaNs pass through unchanged).
template <int W>
inline typename Lanes<W>::V Select(typename Lanes<W>::M mask, typename Lanes<W>::V a,
                                   typename Lanes<W>::V b) {
  using M = typename Lanes<W>::M;
  using V = typename Lanes<W>::V;
  return reinterpret_cast<V>((reinterpret_cast<M>(a) & mask) | (reinterpret_cast<M>(b) & ~mask));
}

// One explicit Euler step of W lanes, processed as blocks of N lanes (N: the widest vector
// of doubles the translation unit's instruction set has, or W if smaller). Blocks of one
// spring are independent, which gives the out-of-order core two or more chains to overlap
// (the square root and division latencies), and keeps every vector in a register.
template <int W, int N>
void StepLanes(const hexgait::BatchKernelArgs& a) {
  static_assert(W % N == 0, "lanes must be a multiple of the block width");
  using V = typename Lanes<N>::V;
  using M = typename Lanes<N>::M;
  const int n = a.num_particles;
  const int ns = a.num_springs;
  const int* __restrict sa = a.spring_a;
  const int* __restrict sb = a.spring_b;
  const double* __restrict k = a.stiffness;
  const double* __restrict c = a.damping;
  const double* __restrict mass = a.mass;
  const double* __restrict inv_mass = a.inv_mass;
  double* __restrict x = a.x;
  double* __restrict y = a.y;
  double* __restrict z = a.z;
  double* __restrict vx = a.vx;
  double* __restrict vy = a.vy;
  double* __restrict vz = a.vz;
  const double* __restrict rest = a.rest_length;
  double* __restrict fx = a.fx;
  double* __restrict fy = a.fy;
  double* __restrict fz = a.fz;
  const double g = a.gravity;

  const V zero = Broadcast<N>(0.0);
  for (int i = 0; i < n; ++i) {
    const V weight = Broadcast<N>(-mass[i] * g);
    for (int b = i * W; b < (i + 1) * W; b += N) {
      Store<N>(fx + b, zero);
      Store<N>(fy + b, zero);
      Store<N>(fz + b, weight);
    }
  }

  // Springs: f = (k (L - L0) + c dL/dt) u, added to both ends in spring order (the order each
  // particle's force is summed in, as in the scalar kernel).
  for (int s = 0; s < ns; ++s) {
    const double ks = k[s], cs = c[s];
    for (int b = 0; b < W; b += N) {
      const int ia = sa[s] * W + b, ib = sb[s] * W + b;
      const V dx = Load<N>(x + ib) - Load<N>(x + ia);
      const V dy = Load<N>(y + ib) - Load<N>(y + ia);
      const V dz = Load<N>(z + ib) - Load<N>(z + ia);
      const V length = Sqrt<N>(dx * dx + dy * dy + dz * dz);
      const V inv = 1.0 / length;
      const V ux = dx * inv, uy = dy * inv, uz = dz * inv;
      const V rate = (Load<N>(vx + ib) - Load<N>(vx + ia)) * ux +
                     (Load<N>(vy + ib) - Load<N>(vy + ia)) * uy +
                     (Load<N>(vz + ib) - Load<N>(vz + ia)) * uz;
      const V magnitude = ks * (length - Load<N>(rest + s * W + b)) + cs * rate;
      const V sfx = magnitude * ux, sfy = magnitude * uy, sfz = magnitude * uz;
      Store<N>(fx + ia, Load<N>(fx + ia) + sfx);
      Store<N>(fy + ia, Load<N>(fy + ia) + sfy);
      Store<N>(fz + ia, Load<N>(fz + ia) + sfz);
      Store<N>(fx + ib, Load<N>(fx + ib) - sfx);
      Store<N>(fy + ib, Load<N>(fy + ib) - sfy);
      Store<N>(fz + ib, Load<N>(fz + ib) - sfz);
    }
  }

  // Ground, per lane exactly as the scalar kernel: skipped when z >= 0 or the normal force
  // would pull (a NaN takes neither exit there, so it must not here either). A block of lanes
  // none of which can touch is skipped as a whole: most body particles, most of the time.
  const double kg = a.ground_stiffness, dg = a.ground_damping, mu = a.friction;
  const double eps2 = a.slip_velocity2;
  for (int e = 0; e < n * W; e += N) {
    const V zi = Load<N>(z + e);
    const M above = zi >= 0.0;
    bool all_above = true;
    for (int l = 0; l < N; ++l) all_above = all_above && above[l] != 0;
    if (all_above) continue;
    const V vxi = Load<N>(vx + e), vyi = Load<N>(vy + e), vzi = Load<N>(vz + e);
    const V normal = -kg * zi - dg * vzi;
    const M apply = ~above & ~(normal <= 0.0);
    const V scale = mu * normal / Sqrt<N>(vxi * vxi + vyi * vyi + eps2);
    const V fxi = Load<N>(fx + e), fyi = Load<N>(fy + e), fzi = Load<N>(fz + e);
    Store<N>(fz + e, Select<N>(apply, fzi + normal, fzi));
    Store<N>(fx + e, Select<N>(apply, fxi - scale * vxi, fxi));
    Store<N>(fy + e, Select<N>(apply, fyi - scale * vyi, fyi));
  }

  // Explicit Euler: positions from the old velocities, velocities from the forces.
  const double dt = a.dt;
  for (int i = 0; i < n; ++i) {
    const double h = dt * inv_mass[i];
    for (int e = i * W; e < (i + 1) * W; e += N) {
      const V vxi = Load<N>(vx + e), vyi = Load<N>(vy + e), vzi = Load<N>(vz + e);
      Store<N>(x + e, Load<N>(x + e) + dt * vxi);
      Store<N>(y + e, Load<N>(y + e) + dt * vyi);
      Store<N>(z + e, Load<N>(z + e) + dt * vzi);
      Store<N>(vx + e, vxi + h * Load<N>(fx + e));
      Store<N>(vy + e, vyi + h * Load<N>(fy + e));
      Store<N>(vz + e, vzi + h * Load<N>(fz + e));
    }
  }
}

constexpr int Block(int lanes) {
  return lanes < HEXGAIT_BATCH_NATIVE_LANES ? lanes : HEXGAIT_BATCH_NATIVE_LANES;
}

// The machine's peak for the kernel's kind of arithmetic: 16 independent chains of vector
// multiplies and adds (no fused multiply-add: the project compiles with -ffp-contract=off, so
// the kernel cannot use it either). Returns a value that depends on every chain, so nothing is
// optimised away; performs 16 * HEXGAIT_BATCH_NATIVE_LANES flops per iteration.
double PeakLoop(long long iterations, double m, double a) {
  constexpr int N = HEXGAIT_BATCH_NATIVE_LANES;
  using V = typename Lanes<N>::V;
  V p[8], q[8];
  for (int j = 0; j < 8; ++j) {
    p[j] = Broadcast<N>(1.0 + j);
    q[j] = Broadcast<N>(2.0 + j);
  }
  for (long long it = 0; it < iterations; ++it) {
    for (int j = 0; j < 8; ++j) {
      p[j] = p[j] * m;
      q[j] = q[j] + a;
    }
  }
  double sum = 0;
  for (int j = 0; j < 8; ++j) {
    for (int l = 0; l < N; ++l) sum += p[j][l] + q[j][l];
  }
  return sum;
}

// The square-root-and-divide floor: 8 independent chains of x <- 1 / sqrt(x) on full vectors
// (x converges to 1, so no denormals). Performs 8 square roots and 8 divisions of
// HEXGAIT_BATCH_NATIVE_LANES lanes per iteration.
double SqrtDivLoop(long long iterations, double seed) {
  constexpr int N = HEXGAIT_BATCH_NATIVE_LANES;
  using V = typename Lanes<N>::V;
  V p[8];
  for (int j = 0; j < 8; ++j) p[j] = Broadcast<N>(seed + j);
  for (long long it = 0; it < iterations; ++it) {
    for (int j = 0; j < 8; ++j) p[j] = 1.0 / Sqrt<N>(p[j]);
  }
  double sum = 0;
  for (int j = 0; j < 8; ++j) {
    for (int l = 0; l < N; ++l) sum += p[j][l];
  }
  return sum;
}

// The table a translation unit exports: index j holds the kernel for kBatchLaneCounts[j].
constexpr hexgait::BatchStepFn kStepTable[] = {StepLanes<1, Block(1)>, StepLanes<2, Block(2)>,
                                               StepLanes<4, Block(4)>, StepLanes<8, Block(8)>,
                                               StepLanes<16, Block(16)>};

}  // namespace
