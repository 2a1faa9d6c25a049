// The classic fourth-order Runge-Kutta method on the 6N first-order equations, four force
// evaluations per step. Stage rest lengths are the motor's at the stage times: L(t_k),
// L(t_k + dt/2) (the mean of the two ends, exact for piecewise-linear lengths with kinks on the
// step grid) and L(t_k + dt).
#pragma once

#include <array>
#include <vector>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

class Rk4Stepper {
 public:
  explicit Rk4Stepper(const CreatureModel& model);
  // Remembers the rest lengths at the start of the first step.
  void Begin(const CreatureModel& model, SimState& state);
  void Step(const CreatureModel& model, SimState& state, double dt);

 private:
  // By axis: the stage state (position, velocity) and the weighted sums of the stage
  // derivatives (velocity, acceleration).
  std::array<std::vector<double>, 3> stage_position_, stage_velocity_;
  std::array<std::vector<double>, 3> sum_velocity_, sum_acceleration_;
  std::vector<double> acceleration_;           // one stage's, one axis at a time
  std::vector<double> rest_start_, rest_mid_;  // L(t_k), L(t_k + dt/2)
};

}  // namespace hexgait
