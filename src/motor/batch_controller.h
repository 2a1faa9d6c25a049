// MotorController for a batch of creatures in lock-step: the program and its timing are shared
// (every lane starts and ends each transition at the same step), only the rest-length tables
// differ. Rest lengths are lane-interleaved ([spring * lanes + lane], see sim/batch_state.h),
// and every lane gets exactly the values MotorController would give it.
#pragma once

#include <utility>
#include <vector>

#include "model/creature.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "simd/aligned.h"
#include "simd/isa.h"

namespace hexgait {

class BatchMotorController {
 public:
  // One table per lane. The rest lengths it writes are lane-interleaved
  // ([spring * lanes + lane]) unless `lane_pitch` is given: then lane l's spring s is at
  // [l * lane_pitch + s] (sim/creature_simulation.h: one creature's springs contiguous), and
  // each step in transition rewrites all of them, as vectors over the springs.
  BatchMotorController(const CreatureModel& model, const MotorProgram& program,
                       std::vector<RestLengthTable> tables, double dt, int lane_pitch = 0);

  // T: double, or float for float lanes (values are computed in double, then rounded).
  template <class T>
  void Update(long long step, T* rest_length) {
    while (step >= cursor_.next_step) Start(step, rest_length);
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
  // Index of lane l's spring s in from_ and change_, and in the caller's rest lengths.
  size_t Cell(int s, int l) const {
    return creature_major_ ? static_cast<size_t>(l) * lane_pitch_ + s
                           : static_cast<size_t>(s) * lanes_ + l;
  }
  size_t Out(int s, int l) const {
    return creature_major_ ? static_cast<size_t>(l) * lane_pitch_ + s
                           : static_cast<size_t>(s) * lanes_ + l;
  }

  // A transition's start and its change (target - start), at Cell(spring, lane).
  // 64-byte aligned, like the kernel's arrays: whole-vector loads never straddle cache lines.
  LaneArrayT<double> from_, change_;
  bool creature_major_;
  int lane_pitch_;
  bool primed_ = false;  // creature-major: from_ holds every spring's value
  // Creature-major: per spring, the step its last transition started at, and its fraction now.
  LaneArrayT<double> start_, fraction_;
  // Vectorised for this CPU (simd/isa.h).
  const BatchIsaKernels& kernels_ = SelectBatchKernels();
  std::vector<Transition> transition_;
  // Per leg, its springs as runs of consecutive indices (first, count): lane-major, a run is
  // one contiguous span of rest lengths, interpolated in one call.
  std::vector<std::vector<std::pair<int, int>>> spring_runs_;
  int num_moving_ = 0;
  EventCursor cursor_;
};

}  // namespace hexgait
