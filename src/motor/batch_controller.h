// MotorController for a batch of creatures in lock-step: the program and its timing are shared
// (every lane starts and ends each transition at the same step), only the rest-length tables
// differ. Rest lengths are lane-interleaved ([spring * lanes + lane], see sim/batch_state.h),
// and every lane gets exactly the values MotorController would give it.
#pragma once

#include <vector>

#include "model/creature.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"

namespace hexgait {

class BatchMotorController {
 public:
  // One table per lane.
  BatchMotorController(const CreatureModel& model, const MotorProgram& program,
                       std::vector<RestLengthTable> tables, double dt);

  // T: double, or float for float lanes (values are computed in double, then rounded).
  template <class T>
  void Update(long long step, T* rest_length) {
    while (step >= next_step_) Start(step, rest_length);
    if (num_moving_ > 0) Move(step, rest_length);
  }

  int lanes() const { return lanes_; }
  double cycle_period() const { return cycle_period_; }

 private:
  struct Transition {
    long long start = 0;
    bool moving = false;
  };
  template <class T>
  void Start(long long step, T* rest_length);
  template <class T>
  void Move(long long step, T* rest_length);

  const CreatureModel& model_;
  int lanes_;
  // Targets, lane-interleaved like the rest lengths: [(position * springs + spring) * lanes +
  // lane].
  std::vector<double> targets_;
  std::vector<Instruction> events_;
  double cycle_period_;
  double dt_;
  long long transition_steps_;
  std::vector<double> from_, to_;  // [spring * lanes + lane]
  // Vectorised for this CPU (sim/batch_kernel.h): a spring's lanes in one call.
  LaneInterpolateFnT<double> interpolate_ = SelectLaneInterpolateT<double>();
  LaneInterpolateFnT<float> interpolate_float_ = SelectLaneInterpolateT<float>();
  std::vector<Transition> transition_;
  int num_moving_ = 0;
  size_t next_event_ = 0;
  long long cycle_ = 0;
  long long next_step_ = 0;
};

}  // namespace hexgait
