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
  double* __restrict p = a.state;  // particle i: x, y, z, vx, vy, vz at (6 i + 0..5) W
  double* __restrict f = a.force;  // particle i: fx, fy, fz at (3 i + 0..2) W
  const double* __restrict rest = a.rest_length;
  const double g = a.gravity;
  enum { X = 0, Y = W, Z = 2 * W, VX = 3 * W, VY = 4 * W, VZ = 5 * W };  // offsets in a block
  enum { FX = 0, FY = W, FZ = 2 * W };

  const V zero = Broadcast<N>(0.0);
  for (int i = 0; i < n; ++i) {
    const V weight = Broadcast<N>(-mass[i] * g);
    for (int b = 0; b < W; b += N) {
      double* fi = f + 3 * W * i + b;
      Store<N>(fi + FX, zero);
      Store<N>(fi + FY, zero);
      Store<N>(fi + FZ, weight);
    }
  }

  // Springs: f = (k (L - L0) + c dL/dt) u, added to both ends in spring order (the order each
  // particle's force is summed in, as in the scalar kernel).
  for (int s = 0; s < ns; ++s) {
    const double ks = k[s], cs = c[s];
    const double* pa0 = p + 6 * W * sa[s];
    const double* pb0 = p + 6 * W * sb[s];
    double* fa0 = f + 3 * W * sa[s];
    double* fb0 = f + 3 * W * sb[s];
    for (int b = 0; b < W; b += N) {
      const double* pa = pa0 + b;
      const double* pb = pb0 + b;
      const V dx = Load<N>(pb + X) - Load<N>(pa + X);
      const V dy = Load<N>(pb + Y) - Load<N>(pa + Y);
      const V dz = Load<N>(pb + Z) - Load<N>(pa + Z);
      const V length = Sqrt<N>(dx * dx + dy * dy + dz * dz);
      const V inv = 1.0 / length;
      const V ux = dx * inv, uy = dy * inv, uz = dz * inv;
      const V rate = (Load<N>(pb + VX) - Load<N>(pa + VX)) * ux +
                     (Load<N>(pb + VY) - Load<N>(pa + VY)) * uy +
                     (Load<N>(pb + VZ) - Load<N>(pa + VZ)) * uz;
      const V magnitude = ks * (length - Load<N>(rest + s * W + b)) + cs * rate;
      const V sfx = magnitude * ux, sfy = magnitude * uy, sfz = magnitude * uz;
      double* fa = fa0 + b;
      double* fb = fb0 + b;
      Store<N>(fa + FX, Load<N>(fa + FX) + sfx);
      Store<N>(fa + FY, Load<N>(fa + FY) + sfy);
      Store<N>(fa + FZ, Load<N>(fa + FZ) + sfz);
      Store<N>(fb + FX, Load<N>(fb + FX) - sfx);
      Store<N>(fb + FY, Load<N>(fb + FY) - sfy);
      Store<N>(fb + FZ, Load<N>(fb + FZ) - sfz);
    }
  }

  // Ground, per lane exactly as the scalar kernel: skipped when z >= 0 or the normal force
  // would pull (a NaN takes neither exit there, so it must not here either). A block of lanes
  // none of which can touch is skipped as a whole: most body particles, most of the time.
  const double kg = a.ground_stiffness, dg = a.ground_damping, mu = a.friction;
  const double eps2 = a.slip_velocity2;
  for (int i = 0; i < n; ++i) {
    for (int b = 0; b < W; b += N) {
      const double* pi = p + 6 * W * i + b;
      double* fi = f + 3 * W * i + b;
      const V zi = Load<N>(pi + Z);
      const M above = zi >= 0.0;
      bool all_above = true;
      for (int l = 0; l < N; ++l) all_above = all_above && above[l] != 0;
      if (all_above) continue;
      const V vxi = Load<N>(pi + VX), vyi = Load<N>(pi + VY), vzi = Load<N>(pi + VZ);
      const V normal = -kg * zi - dg * vzi;
      const M apply = ~above & ~(normal <= 0.0);
      const V scale = mu * normal / Sqrt<N>(vxi * vxi + vyi * vyi + eps2);
      const V fxi = Load<N>(fi + FX), fyi = Load<N>(fi + FY), fzi = Load<N>(fi + FZ);
      Store<N>(fi + FZ, Select<N>(apply, fzi + normal, fzi));
      Store<N>(fi + FX, Select<N>(apply, fxi - scale * vxi, fxi));
      Store<N>(fi + FY, Select<N>(apply, fyi - scale * vyi, fyi));
    }
  }

  // Explicit Euler: positions from the old velocities, velocities from the forces.
  const double dt = a.dt;
  for (int i = 0; i < n; ++i) {
    const double h = dt * inv_mass[i];
    for (int b = 0; b < W; b += N) {
      double* pi = p + 6 * W * i + b;
      const double* fi = f + 3 * W * i + b;
      const V vxi = Load<N>(pi + VX), vyi = Load<N>(pi + VY), vzi = Load<N>(pi + VZ);
      Store<N>(pi + X, Load<N>(pi + X) + dt * vxi);
      Store<N>(pi + Y, Load<N>(pi + Y) + dt * vyi);
      Store<N>(pi + Z, Load<N>(pi + Z) + dt * vzi);
      Store<N>(pi + VX, vxi + h * Load<N>(fi + FX));
      Store<N>(pi + VY, vyi + h * Load<N>(fi + FY));
      Store<N>(pi + VZ, vzi + h * Load<N>(fi + FZ));
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
