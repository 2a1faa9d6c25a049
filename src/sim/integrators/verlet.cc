#include "sim/integrators/verlet.h"

#include "sim/forces.h"
#include "sim/integrators/axis_loops.h"

namespace hexgait {

VerletStepper::VerletStepper(const CreatureModel& model) {
  for (int a = 0; a < 3; ++a) {
    acceleration_[a].assign(model.num_particles(), 0.0);
    predicted_velocity_[a].assign(model.num_particles(), 0.0);
  }
}

void VerletStepper::Begin(const CreatureModel& model, SimState& s) {
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  const std::array<Axis, 3> axes = Axes(s);
  for (int a = 0; a < 3; ++a) {
    Accelerations(s.num_particles(), model.inv_mass.data(), axes[a].force, acceleration_[a].data());
  }
}

void VerletStepper::Step(const CreatureModel& model, SimState& s, double dt) {
  const int n = s.num_particles();
  const double half = 0.5 * dt;
  const std::array<Axis, 3> axes = Axes(s);
  // Kick half a step, drift a whole one, and predict the end-of-step velocity.
  for (int a = 0; a < 3; ++a) {
    AddScaled(n, half, acceleration_[a].data(), axes[a].velocity);
    AddScaled(n, dt, axes[a].velocity, axes[a].position);
    ScaledSum(n, axes[a].velocity, half, acceleration_[a].data(), predicted_velocity_[a].data());
  }
  // Forces at the new positions, the predicted velocities and the end-of-step rest lengths.
  const ParticleView at_end{s.x.data(),
                            s.y.data(),
                            s.z.data(),
                            predicted_velocity_[0].data(),
                            predicted_velocity_[1].data(),
                            predicted_velocity_[2].data()};
  ComputeForces(model, s.rest_length.data(), at_end, s.force_view());
  for (int a = 0; a < 3; ++a) {
    Accelerations(n, model.inv_mass.data(), axes[a].force, acceleration_[a].data());
    AddScaled(n, half, acceleration_[a].data(), axes[a].velocity);
  }
  ++s.step;
}

}  // namespace hexgait
