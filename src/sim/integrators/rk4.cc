#include "sim/integrators/rk4.h"

#include <algorithm>

#include "sim/forces.h"
#include "sim/integrators/axis_loops.h"

namespace hexgait {

Rk4Stepper::Rk4Stepper(const CreatureModel& model) {
  const size_t n = model.num_particles();
  for (int a = 0; a < 3; ++a) {
    for (std::vector<double>* v :
         {&stage_position_[a], &stage_velocity_[a], &sum_velocity_[a], &sum_acceleration_[a]}) {
      v->assign(n, 0.0);
    }
  }
  acceleration_.assign(n, 0.0);
  rest_start_.assign(model.num_springs(), 0.0);
  rest_mid_.assign(model.num_springs(), 0.0);
}

void Rk4Stepper::Begin(const CreatureModel&, SimState& s) {
  std::copy(s.rest_length.begin(), s.rest_length.end(), rest_start_.begin());
}

void Rk4Stepper::Step(const CreatureModel& model, SimState& s, double dt) {
  const int n = s.num_particles();
  const int ns = model.num_springs();
  for (int k = 0; k < ns; ++k) rest_mid_[k] = 0.5 * (rest_start_[k] + s.rest_length[k]);
  const double* rest[4] = {rest_start_.data(), rest_mid_.data(), rest_mid_.data(),
                           s.rest_length.data()};
  // Stage j's derivative enters the sum with weight[j]; the next stage is taken at
  // y_k + next[j] * dt * (stage j's derivative).
  static constexpr double kWeight[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
  static constexpr double kNext[4] = {0.5, 0.5, 1.0, 0.0};

  const std::array<Axis, 3> axes = Axes(s);
  for (int a = 0; a < 3; ++a) {
    std::copy_n(axes[a].position, n, stage_position_[a].begin());
    std::copy_n(axes[a].velocity, n, stage_velocity_[a].begin());
    std::fill(sum_velocity_[a].begin(), sum_velocity_[a].end(), 0.0);
    std::fill(sum_acceleration_[a].begin(), sum_acceleration_[a].end(), 0.0);
  }
  const ParticleView stage{stage_position_[0].data(), stage_position_[1].data(),
                           stage_position_[2].data(), stage_velocity_[0].data(),
                           stage_velocity_[1].data(), stage_velocity_[2].data()};
  for (int j = 0; j < 4; ++j) {
    ComputeForces(model, rest[j], stage, s.force_view());
    const double w = kWeight[j], c = kNext[j] * dt;
    for (int a = 0; a < 3; ++a) {
      // Stage derivative: (velocity, acceleration) = (stage velocity, f / m).
      double* sv = stage_velocity_[a].data();
      Accelerations(n, model.inv_mass.data(), axes[a].force, acceleration_.data());
      AddScaled(n, w, sv, sum_velocity_[a].data());
      AddScaled(n, w, acceleration_.data(), sum_acceleration_[a].data());
      ScaledSum(n, axes[a].position, c, sv, stage_position_[a].data());
      ScaledSum(n, axes[a].velocity, c, acceleration_.data(), sv);
    }
  }
  for (int a = 0; a < 3; ++a) {
    AddScaled(n, dt, sum_velocity_[a].data(), axes[a].position);
    AddScaled(n, dt, sum_acceleration_[a].data(), axes[a].velocity);
  }
  std::copy(s.rest_length.begin(), s.rest_length.end(), rest_start_.begin());
  ++s.step;
}

}  // namespace hexgait
