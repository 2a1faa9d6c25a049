// The reference solution the integrators are measured against: Boost.Odeint's adaptive
// Dormand-Prince 5(4) stepper on the same 6N equations (forces.h), with the motor's rest lengths
// as the continuous function of time of motor/rest_schedule.h. Integration restarts at every
// kink of the rest lengths, so the stepper never steps across one; contact still makes the
// right-hand side non-smooth, which the step-size control handles by rejecting steps.
#pragma once

#include <vector>

#include "model/creature.h"
#include "motor/rest_schedule.h"
#include "sim/state.h"

namespace hexgait {

class ReferenceSolver {
 public:
  // `tolerance` is both the absolute and the relative error tolerance per step. Without a
  // schedule (nullptr) the rest lengths stay those of `initial`.
  ReferenceSolver(const CreatureModel& model, const RestLengthSchedule* schedule,
                  const SimState& initial, double tolerance);

  // Integrates on to time t (at or after the current time).
  void AdvanceTo(double t);
  // Positions, velocities and rest lengths at the current time.
  const SimState& state() const { return state_; }
  double time() const { return time_; }
  long long steps() const { return steps_; }  // accepted adaptive steps so far

 private:
  void Sync();  // copies y_ into state_

  const CreatureModel& model_;
  const RestLengthSchedule* schedule_;
  std::vector<double> fixed_rest_;
  double tolerance_;
  std::vector<double> y_;  // x, y, z, vx, vy, vz, each N long
  SimState state_;
  double time_ = 0;
  double step_guess_ = 1e-3;
  long long steps_ = 0;
};

}  // namespace hexgait
