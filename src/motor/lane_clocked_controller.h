// MotorController for lanes that each run their own creature on their own clock: when a lane's
// creature finishes (it fell under stop_at_fall, diverged, came to rest), the lane takes the
// next creature at once, which starts its program at step 0 while the other lanes are mid-way
// through theirs. So, unlike BatchMotorController, nothing is shared but the program: every
// lane has its own offset, next instruction and transitions, and gets exactly the rest lengths
// MotorController would give its creature at the creature's own step (BatchMotorController's
// values for T = float: computed in double from the lane's current float values, then rounded).
// Rest lengths are lane-interleaved, [spring * lanes + lane], as in sim/batch_state.h.
//
// While any transition runs, every leg spring of every lane is rewritten each step from
// (from, change, fraction), as whole vectors: a transition's fraction comes from its start in
// the batch's steps (exact integers in double), a finished one stays at 1 and a leg that has not
// moved yet has no change, so the values are the scalar controller's and the rest rewrite
// themselves unchanged.
#pragma once

#include <vector>

#include "model/creature.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "simd/aligned.h"
#include "simd/isa.h"

namespace hexgait {

class LaneClockedController {
 public:
  LaneClockedController(const CreatureModel& model, const MotorProgram& program, int lanes,
                        double dt);

  // Lane `lane` starts a creature with `table` whose step 0 is the batch's step `step`, from
  // the rest lengths the lane holds now (`rest_length`, lane-interleaved).
  template <class T>
  void StartLane(int lane, const RestLengthTable& table, long long step, const T* rest_length);
  // The lane runs no creature any more: it gets no further instruction.
  void StopLane(int lane) { lane_[static_cast<size_t>(lane)].active = false; }

  // Before the batch's step `step`: every active lane's due instructions, then the transitions.
  // T: double, or float for float lanes. Does not allocate.
  template <class T>
  void Update(long long step, T* rest_length) {
    for (int l = 0; l < lanes_; ++l) {
      Lane& lane = lane_[static_cast<size_t>(l)];
      if (lane.active) {
        while (step - lane.offset >= lane.cursor.next_step) Start(l, step, rest_length);
      }
    }
    if (step < moving_until_) Move(step, rest_length);
  }

  int lanes() const { return lanes_; }
  double cycle_period() const { return cycle_period_; }

 private:
  struct Lane {
    bool active = false;
    long long offset = 0;         // the batch's step at the creature's step 0
    std::vector<double> targets;  // the creature's table: [position * springs + spring]
    EventCursor cursor;           // in the creature's steps
  };
  template <class T>
  void Start(int l, long long step, T* rest_length);
  template <class T>
  void Move(long long step, T* rest_length);

  const CreatureModel& model_;
  int lanes_;
  std::vector<Instruction> events_;
  double cycle_period_;
  double dt_;
  long long transition_steps_;
  std::vector<Lane> lane_;
  std::vector<int> leg_springs_, leg_of_;  // every leg spring, and its leg
  // Lane-interleaved: per spring [s * lanes + l] the transition's start value and (to - from);
  // per leg [leg * lanes + l] the batch's step its transition started at, and its fraction.
  LaneArrayT<double> from_, change_, start_, fraction_;
  long long moving_until_ = 0;  // no transition runs at this batch step or after
  const BatchIsaKernels& kernels_ = SelectBatchKernels();
};

}  // namespace hexgait
