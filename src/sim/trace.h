// An observer that samples the run every few steps: body centre, lowest body particle, tilt,
// and which feet touch the ground. Used by `simulate --csv` and the figures.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

struct TraceSample {
  double time = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double lowest_body = 0;
  double tilt_degrees = 0;
  double pitch_degrees = 0;  // see BodyPitchRollDegrees
  double roll_degrees = 0;
  unsigned feet_on_ground = 0;  // bit i: leg i's foot touches the ground
};

// A foot closer to the ground than this counts as touching it (the penalty contact lets a
// loaded foot sink slightly below z = 0).
inline constexpr double kFootContactHeight = 0.005;

// Bit l set: leg l's foot touches the ground. A lost leg's loose foot never counts
// (model/damage.h): it touches the ground, but it is no longer a foot the creature stands on.
// `height(i)`: particle i's height (the lanes read theirs from the batch's state).
template <class Height>
uint32_t FeetOnGroundAt(const CreatureModel& model, const Height& height) {
  uint32_t feet = 0;
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    if (height(model.legs[leg].foot) < kFootContactHeight) feet |= 1u << leg;
  }
  return feet & ~model.lost_legs;
}
inline uint32_t FeetOnGround(const CreatureModel& model, const SimState& s) {
  return FeetOnGroundAt(model, [&s](int i) { return s.z[i]; });
}

class TraceRecorder {
 public:
  TraceRecorder(const CreatureModel& model, long long every_steps)
      : model_(model), every_(every_steps), until_(every_steps) {}

  void Record(const SimState& s) {
    TraceSample t;
    t.time = s.time;
    t.centre = BodyCentre(model_, s);
    t.lowest_body = LowestBodyHeight(model_, s);
    t.tilt_degrees = BodyTiltDegrees(model_, s);
    BodyPitchRollDegrees(model_, s, &t.pitch_degrees, &t.roll_degrees);
    t.feet_on_ground = FeetOnGround(model_, s);
    samples_.push_back(t);
  }
  void OnStep(const SimState& s) {
    if (--until_ == 0) {
      until_ = every_;
      Record(s);
    }
  }
  const std::vector<TraceSample>& samples() const { return samples_; }

 private:
  const CreatureModel& model_;
  long long every_;
  long long until_;
  std::vector<TraceSample> samples_;
};

}  // namespace hexgait
