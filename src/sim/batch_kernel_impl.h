// The batched explicit-Euler kernel's source, included by one translation unit per
// instruction set (batch_kernel_generic.cc, _avx2.cc, _avx512.cc), each compiled with its own
// -m flags. Everything here has internal linkage and calls only compiler builtins: an inline
// function with external linkage compiled for AVX-512 could otherwise be picked by the linker
// for every caller and fault on a CPU without it.
//
// Each lane loop below has a compile-time trip count W and no cross-lane dependence, so GCC
// turns it into W / (vector width) vector instructions. Per lane, the operations and their
// order are exactly those of ComputeForces and EulerStepper::Step (sim/forces.cc,
// sim/integrator.cc): that is what makes a lane bit-identical to the scalar path.
#include "sim/batch_kernel_args.h"

namespace {

template <int W>
void StepLanes(const hexgait::BatchKernelArgs& a) {
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
  double* __restrict sfx = a.spring_fx;
  double* __restrict sfy = a.spring_fy;
  double* __restrict sfz = a.spring_fz;
  const double g = a.gravity;

  for (int i = 0; i < n; ++i) {
    const double weight = -mass[i] * g;
    for (int l = 0; l < W; ++l) {
      fx[i * W + l] = 0;
      fy[i * W + l] = 0;
      fz[i * W + l] = weight;
    }
  }

  // Springs: f = (k (L - L0) + c dL/dt) u, every spring first, then the scatter in spring
  // order (the order each particle's force is summed in, as in the scalar kernel).
  for (int s = 0; s < ns; ++s) {
    const int ia = sa[s] * W, ib = sb[s] * W;
    const double ks = k[s], cs = c[s];
    for (int l = 0; l < W; ++l) {
      const double dx = x[ib + l] - x[ia + l], dy = y[ib + l] - y[ia + l],
                   dz = z[ib + l] - z[ia + l];
      const double length = __builtin_sqrt(dx * dx + dy * dy + dz * dz);
      const double inv = 1.0 / length;
      const double ux = dx * inv, uy = dy * inv, uz = dz * inv;
      const double rate = (vx[ib + l] - vx[ia + l]) * ux + (vy[ib + l] - vy[ia + l]) * uy +
                          (vz[ib + l] - vz[ia + l]) * uz;
      const double magnitude = ks * (length - rest[s * W + l]) + cs * rate;
      sfx[s * W + l] = magnitude * ux;
      sfy[s * W + l] = magnitude * uy;
      sfz[s * W + l] = magnitude * uz;
    }
  }
  for (int s = 0; s < ns; ++s) {
    const int ia = sa[s] * W, ib = sb[s] * W;
    for (int l = 0; l < W; ++l) {
      fx[ia + l] += sfx[s * W + l];
      fy[ia + l] += sfy[s * W + l];
      fz[ia + l] += sfz[s * W + l];
    }
    for (int l = 0; l < W; ++l) {
      fx[ib + l] -= sfx[s * W + l];
      fy[ib + l] -= sfy[s * W + l];
      fz[ib + l] -= sfz[s * W + l];
    }
  }

  // Ground, per lane exactly as the scalar kernel: skipped when z >= 0 or the normal force
  // would pull (a NaN takes neither exit there, so it must not here either). A particle no
  // lane can touch is skipped as a whole: most body particles, most of the time.
  const double kg = a.ground_stiffness, dg = a.ground_damping, mu = a.friction;
  const double eps2 = a.slip_velocity2;
  for (int i = 0; i < n; ++i) {
    double* __restrict zi = z + i * W;
    bool any = false;
    for (int l = 0; l < W; ++l) any |= !(zi[l] >= 0);
    if (!any) continue;
    for (int l = 0; l < W; ++l) {
      const int e = i * W + l;
      const double normal = -kg * z[e] - dg * vz[e];
      const bool apply = !(z[e] >= 0) && !(normal <= 0);
      const double scale = mu * normal / __builtin_sqrt(vx[e] * vx[e] + vy[e] * vy[e] + eps2);
      const double fz_contact = fz[e] + normal;
      const double fx_contact = fx[e] - scale * vx[e];
      const double fy_contact = fy[e] - scale * vy[e];
      fz[e] = apply ? fz_contact : fz[e];
      fx[e] = apply ? fx_contact : fx[e];
      fy[e] = apply ? fy_contact : fy[e];
    }
  }

  // Explicit Euler: positions from the old velocities, velocities from the forces.
  const double dt = a.dt;
  for (int i = 0; i < n; ++i) {
    const double h = dt * inv_mass[i];
    for (int l = 0; l < W; ++l) {
      const int e = i * W + l;
      x[e] += dt * vx[e];
      y[e] += dt * vy[e];
      z[e] += dt * vz[e];
      vx[e] += h * fx[e];
      vy[e] += h * fy[e];
      vz[e] += h * fz[e];
    }
  }
}

// The table a translation unit exports: index j holds the kernel for kBatchLaneCounts[j].
constexpr hexgait::BatchStepFn kStepTable[] = {StepLanes<1>, StepLanes<2>, StepLanes<4>,
                                               StepLanes<8>, StepLanes<16>};

}  // namespace
