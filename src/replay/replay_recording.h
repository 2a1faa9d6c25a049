// What a browser replay needs of one run, recorded while it is simulated: the particles'
// positions at every movie frame (decimated only in time), and what the movie's camera and gait
// cues derive from the run (the follow camera's tracked point, feet down, every footprint and
// trail point), computed here by the same CameraTracker and CueRecorder the movies use, so the
// page shows the frames a movie would without re-deriving them in JavaScript.
#pragma once

#include <cstdint>
#include <vector>

#include "model/creature.h"
#include "movie/cue_recorder.h"
#include "render/camera.h"
#include "sim/state.h"
#include "sim/step_loop.h"

namespace hexgait {

struct ReplayRecording {
  int num_particles = 0;
  int stride = 1;                     // one kept frame per `stride` movie frames
  std::vector<float> time;            // per kept frame
  std::vector<float> position;        // per kept frame, particle-major x, y, z
  std::vector<float> centre;          // per kept frame, the body centre x, y, z
  std::vector<float> follow;          // per kept frame, the point a follow camera looks past
  std::vector<uint8_t> feet_down;     // per kept frame, bit i: leg i's foot is down
  std::vector<Footprint> footprints;  // every touch-down of the run, in time order
  std::vector<TrailPoint> trail;      // every point of the body's trail, in time order
  float foot_radius = 0.1f;
  RunResult result;
  int frames() const { return static_cast<int>(time.size()); }
};

// A simulation observer: samples the run every `every_steps` steps (one movie frame), keeps
// every `stride`-th sample's positions and records all samples' cues. Call Sample once with
// the start state before the run and once with the final state after it, as a still does.
class ReplayRecorder {
 public:
  ReplayRecorder(const CreatureModel& model, double cycle_period, const SimState& start,
                 long long every_steps, int stride, size_t expected_frames);
  void OnStep(const SimState& state) {
    if (--until_ > 0) return;
    until_ = every_;
    Sample(state);
  }
  // `keep_always`: store this state whatever the stride (the first and the last frame).
  void Sample(const SimState& state, bool keep_always = false);
  ReplayRecording Finish(const RunResult& result);

 private:
  const CreatureModel& model_;
  long long every_, until_;
  int stride_;
  long long samples_ = 0;  // distinct times sampled
  double last_time_ = -1;
  CameraTracker follow_;
  CueRecorder cues_;
  size_t prints_seen_ = 0, trail_seen_ = 0;
  ReplayRecording recording_;
};

}  // namespace hexgait
