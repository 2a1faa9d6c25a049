#include "sim/integrators/implicit_euler.h"

#include "sim/forces.h"
#include "sim/jacobian.h"

namespace hexgait {

ImplicitEulerStepper::ImplicitEulerStepper(const CreatureModel& model)
    : df_dx_(3 * model.num_particles(), 3 * model.num_particles()),
      df_dv_(3 * model.num_particles(), 3 * model.num_particles()),
      system_(3 * model.num_particles(), 3 * model.num_particles()),
      velocity_(3 * model.num_particles()),
      rhs_(3 * model.num_particles()),
      dv_(3 * model.num_particles()),
      lu_(3 * model.num_particles()) {}

void ImplicitEulerStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  const int n = s.num_particles();
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  ForceJacobians(model, s.rest_length.data(), s.particle_view(), df_dx_, df_dv_);
  for (int i = 0; i < n; ++i) {
    velocity_.segment<3>(3 * i) << s.vx[i], s.vy[i], s.vz[i];
  }
  // rhs = dt (f + dt K v)
  rhs_.noalias() = df_dx_ * velocity_;
  for (int i = 0; i < n; ++i) {
    rhs_(3 * i + 0) = dt * (s.fx[i] + dt * rhs_(3 * i + 0));
    rhs_(3 * i + 1) = dt * (s.fy[i] + dt * rhs_(3 * i + 1));
    rhs_(3 * i + 2) = dt * (s.fz[i] + dt * rhs_(3 * i + 2));
  }
  system_.noalias() = -(dt * dt) * df_dx_ - dt * df_dv_;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) system_(3 * i + c, 3 * i + c) += model.mass[i];
  }
  lu_.compute(system_);
  dv_.noalias() = lu_.solve(rhs_);
  for (int i = 0; i < n; ++i) {
    s.vx[i] += dv_(3 * i + 0);
    s.vy[i] += dv_(3 * i + 1);
    s.vz[i] += dv_(3 * i + 2);
    s.x[i] += dt * s.vx[i];
    s.y[i] += dt * s.vy[i];
    s.z[i] += dt * s.vz[i];
  }
  ++s.step;
}

}  // namespace hexgait
