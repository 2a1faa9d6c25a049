#include "sim/integrators/implicit_euler.h"

#include "sim/forces.h"
#include "sim/integrators/axis_loops.h"
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
  const std::array<Axis, 3> axes = Axes(s);
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < n; ++i) velocity_(3 * i + a) = axes[a].velocity[i];
  }
  // rhs = dt (f + dt K v)
  rhs_.noalias() = df_dx_ * velocity_;
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < n; ++i) rhs_(3 * i + a) = dt * (axes[a].force[i] + dt * rhs_(3 * i + a));
  }
  system_.noalias() = -(dt * dt) * df_dx_ - dt * df_dv_;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) system_(3 * i + c, 3 * i + c) += model.mass[i];
  }
  lu_.compute(system_);
  dv_.noalias() = lu_.solve(rhs_);
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < n; ++i) axes[a].velocity[i] += dv_(3 * i + a);
    AddScaled(n, dt, axes[a].velocity, axes[a].position);
  }
  ++s.step;
}

}  // namespace hexgait
