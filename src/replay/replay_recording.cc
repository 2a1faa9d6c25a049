#include "replay/replay_recording.h"

namespace hexgait {

ReplayRecorder::ReplayRecorder(const CreatureModel& model, double cycle_period,
                               const SimState& start, long long every_steps, int stride,
                               size_t expected_frames)
    : model_(model),
      every_(every_steps),
      until_(every_steps),
      stride_(stride),
      follow_(CameraSpec::Tracking::kFollow, BodyCentre(model, start).cast<float>()),
      cues_(model, cycle_period) {
  recording_.num_particles = model.num_particles();
  recording_.stride = stride;
  recording_.foot_radius = cues_.history().foot_radius;
  const size_t n = static_cast<size_t>(model.num_particles());
  recording_.time.reserve(expected_frames);
  recording_.position.reserve(expected_frames * n * 3);
  recording_.centre.reserve(expected_frames * 3);
  recording_.follow.reserve(expected_frames * 3);
  recording_.feet_down.reserve(expected_frames);
}

void ReplayRecorder::Sample(const SimState& state, bool keep_always) {
  const bool fresh = state.time != last_time_;  // the final state may fall on a sample
  if (fresh) {
    last_time_ = state.time;
    // Every sample moves the camera and records the cues, as every movie frame does; only the
    // kept ones are stored.
    follow_.Update(BodyCentre(model_, state).cast<float>());
    cues_.Sample(state);
    const GaitHistory& h = cues_.history();
    for (; prints_seen_ < h.footprints.pushed(); ++prints_seen_) {
      recording_.footprints.push_back(
          h.footprints[h.footprints.size() - (h.footprints.pushed() - prints_seen_)]);
    }
    for (; trail_seen_ < h.trail.pushed(); ++trail_seen_) {
      recording_.trail.push_back(h.trail[h.trail.size() - (h.trail.pushed() - trail_seen_)]);
    }
    ++samples_;
  }
  const bool kept_already =
      !recording_.time.empty() && recording_.time.back() == static_cast<float>(state.time);
  const bool keep =
      fresh ? (keep_always || (samples_ - 1) % stride_ == 0) : keep_always && !kept_already;
  if (!keep) return;
  const Eigen::Vector3f centre = BodyCentre(model_, state).cast<float>();
  const Eigen::Vector3f& tracked = follow_.current();
  recording_.time.push_back(static_cast<float>(state.time));
  for (int i = 0; i < model_.num_particles(); ++i) {
    recording_.position.insert(recording_.position.end(),
                               {static_cast<float>(state.x[i]), static_cast<float>(state.y[i]),
                                static_cast<float>(state.z[i])});
  }
  recording_.centre.insert(recording_.centre.end(), {centre.x(), centre.y(), centre.z()});
  recording_.follow.insert(recording_.follow.end(), {tracked.x(), tracked.y(), tracked.z()});
  recording_.feet_down.push_back(static_cast<uint8_t>(cues_.history().feet_down));
}

ReplayRecording ReplayRecorder::Finish(const RunResult& result) {
  recording_.result = result;
  return std::move(recording_);
}

}  // namespace hexgait
