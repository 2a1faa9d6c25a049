#include "sim/integrators/verlet.h"

#include "sim/forces.h"

namespace hexgait {

VerletStepper::VerletStepper(const CreatureModel& model)
    : ax_(model.num_particles()),
      ay_(model.num_particles()),
      az_(model.num_particles()),
      px_(model.num_particles()),
      py_(model.num_particles()),
      pz_(model.num_particles()) {}

void VerletStepper::Begin(const CreatureModel& model, SimState& s) {
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  for (int i = 0; i < s.num_particles(); ++i) {
    ax_[i] = s.fx[i] * model.inv_mass[i];
    ay_[i] = s.fy[i] * model.inv_mass[i];
    az_[i] = s.fz[i] * model.inv_mass[i];
  }
}

void VerletStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  const int n = s.num_particles();
  const double half = 0.5 * dt;
  double* __restrict x = s.x.data();
  double* __restrict y = s.y.data();
  double* __restrict z = s.z.data();
  double* __restrict vx = s.vx.data();
  double* __restrict vy = s.vy.data();
  double* __restrict vz = s.vz.data();
  double* __restrict ax = ax_.data();
  double* __restrict ay = ay_.data();
  double* __restrict az = az_.data();
  double* __restrict px = px_.data();
  double* __restrict py = py_.data();
  double* __restrict pz = pz_.data();
  // Kick half a step, drift a whole one, and predict the end-of-step velocity.
  for (int i = 0; i < n; ++i) {
    vx[i] += half * ax[i];
    vy[i] += half * ay[i];
    vz[i] += half * az[i];
    x[i] += dt * vx[i];
    y[i] += dt * vy[i];
    z[i] += dt * vz[i];
    px[i] = vx[i] + half * ax[i];
    py[i] = vy[i] + half * ay[i];
    pz[i] = vz[i] + half * az[i];
  }
  // Forces at the new positions, the predicted velocities and the end-of-step rest lengths.
  const ParticleView at_end{x, y, z, px, py, pz};
  ComputeForces(model, s.rest_length.data(), at_end, s.force_view());
  const double* __restrict inv_mass = model.inv_mass.data();
  const double* __restrict fx = s.fx.data();
  const double* __restrict fy = s.fy.data();
  const double* __restrict fz = s.fz.data();
  for (int i = 0; i < n; ++i) {
    ax[i] = fx[i] * inv_mass[i];
    ay[i] = fy[i] * inv_mass[i];
    az[i] = fz[i] * inv_mass[i];
    vx[i] += half * ax[i];
    vy[i] += half * ay[i];
    vz[i] += half * az[i];
  }
  ++s.step;
}

}  // namespace hexgait
