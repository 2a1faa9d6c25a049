// The controller's rest lengths as a function of continuous time: piecewise linear, with kinks
// only at instruction times and at the ends of transitions. The adaptive reference solver
// (sim/reference.h) evaluates it at any time; MotorController produces the same values at the
// ends of its steps (Update(k) gives the lengths at t = (k + 1) dt when instruction times and
// the transition time are multiples of dt, as with the default program).
#pragma once

#include <vector>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"

namespace hexgait {

class RestLengthSchedule {
 public:
  // Instructions from t = 0 up to `duration`, starting from the rest lengths `initial`.
  RestLengthSchedule(const CreatureModel& model, const MotorProgram& program,
                     const RestLengthTable& table, std::vector<double> initial, double duration);

  // Writes every spring's rest length at time t (0 <= t <= duration).
  void At(double t, double* rest_length) const;
  // Sorted times in (0, duration) where some rest length has a kink; between two of them every
  // rest length is linear in t.
  const std::vector<double>& breakpoints() const { return breakpoints_; }

 private:
  struct Segment {
    double start = 0;              // instruction time
    std::vector<double> from, to;  // per spring of the leg
  };
  const CreatureModel& model_;
  double transition_time_;
  std::vector<double> initial_;
  std::vector<std::vector<Segment>> segments_;  // per leg, by start time
  std::vector<double> breakpoints_;
};

}  // namespace hexgait
