// Plays a motor program: at each instruction's step, the instructed leg's motor springs get
// the rest lengths of its new position as their target, and travel there linearly over the
// program's transition time. Instruction times are converted to step numbers once, so a step
// with nothing due costs one integer comparison and a loop over the legs still moving.
#pragma once

#include <cmath>
#include <vector>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"

namespace hexgait {

// First step whose start time is at or after `time` (with a tolerance for rounding): when an
// instruction at `time` takes effect.
long long StepAtTime(double time, double dt);

class MotorController {
 public:
  MotorController(const CreatureModel& model, const MotorProgram& program, RestLengthTable table,
                  double dt);

  // Applies every instruction due at or before `step`, and moves rest lengths in transition.
  void Update(long long step, double* rest_length) {
    while (step >= next_step_) Start(step, rest_length);
    if (num_moving_ > 0) Move(step, rest_length);
  }

  double cycle_period() const { return cycle_period_; }
  // 1-based gait cycle containing `time`.
  int CycleOf(double time) const { return static_cast<int>(std::floor(time / cycle_period_)) + 1; }
  const RestLengthTable& table() const { return table_; }

 private:
  struct Transition {
    long long start = 0;
    bool moving = false;
  };
  void Start(long long step, double* rest_length);
  void Move(long long step, double* rest_length);

  const CreatureModel& model_;
  RestLengthTable table_;
  std::vector<Instruction> events_;  // one cycle, sorted by time
  double cycle_period_;
  double dt_;
  long long transition_steps_;
  std::vector<double> from_, to_;       // per spring
  std::vector<Transition> transition_;  // per leg
  int num_moving_ = 0;
  size_t next_event_ = 0;
  long long cycle_ = 0;
  long long next_step_ = 0;
};

}  // namespace hexgait
