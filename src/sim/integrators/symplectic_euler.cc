#include "sim/integrators/symplectic_euler.h"

#include "sim/forces.h"

namespace hexgait {

void SymplecticEulerStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  const int n = s.num_particles();
  const double* __restrict inv_mass = model.inv_mass.data();
  double* __restrict x = s.x.data();
  double* __restrict y = s.y.data();
  double* __restrict z = s.z.data();
  double* __restrict vx = s.vx.data();
  double* __restrict vy = s.vy.data();
  double* __restrict vz = s.vz.data();
  const double* __restrict fx = s.fx.data();
  const double* __restrict fy = s.fy.data();
  const double* __restrict fz = s.fz.data();
  for (int i = 0; i < n; ++i) {
    const double h = dt * inv_mass[i];
    vx[i] += h * fx[i];
    vy[i] += h * fy[i];
    vz[i] += h * fz[i];
    x[i] += dt * vx[i];
    y[i] += dt * vy[i];
    z[i] += dt * vz[i];
  }
  ++s.step;
}

}  // namespace hexgait
