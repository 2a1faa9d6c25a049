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

// Where a program stands: the next instruction to start, the gait cycle it falls in (from 0)
// and the step it starts at. Each controller (scalar, batched, per lane) keeps one.
struct EventCursor {
  size_t next_event = 0;
  long long cycle = 0;
  long long next_step = 0;

  // At the program's first instruction.
  void Reset(const std::vector<Instruction>& events, double dt) {
    next_event = 0;
    cycle = 0;
    next_step = StepAtTime(events.front().time, dt);
  }
  // Past the instruction just started: the one after it, or the first of the next cycle.
  void Advance(const std::vector<Instruction>& events, double cycle_period, double dt) {
    if (++next_event == events.size()) {
      next_event = 0;
      ++cycle;
    }
    next_step = StepAtTime(static_cast<double>(cycle) * cycle_period + events[next_event].time, dt);
  }
};

class MotorController {
 public:
  MotorController(const CreatureModel& model, const MotorProgram& program, RestLengthTable table,
                  double dt);

  // Applies every instruction due at or before `step`, and moves rest lengths in transition.
  void Update(long long step, double* rest_length) {
    while (step >= cursor_.next_step) Start(step, rest_length);
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
  EventCursor cursor_;
};

}  // namespace hexgait
