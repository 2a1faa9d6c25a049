// Fills a GaitHistory (render/gait_cues.h) from the simulation, once per frame: which feet are
// down, touch-downs as footprints, the body centre's path. Bounded ring buffers, so a movie's
// memory stays flat; a few hundred nanoseconds per frame.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/creature.h"
#include "render/gait_cues.h"
#include "sim/state.h"

namespace hexgait {

class CueRecorder {
 public:
  CueRecorder(const CreatureModel& model, double cycle_period);
  // Call once per frame, in time order; the first call records the feet already down.
  void Sample(const SimState& state);
  const GaitHistory& history() const { return history_; }

 private:
  const CreatureModel& model_;
  GaitHistory history_;
  std::vector<Eigen::Vector2f> last_print_;  // per leg, to merge a foot's bounces into one print
};

}  // namespace hexgait
