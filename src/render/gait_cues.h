// Gait cues drawn over a movie frame so the stepping pattern stays visible: footprints on the
// ground, the body's trail, the swinging legs highlighted, and a scrolling footfall strip. This
// header holds which cues are on and the history they draw from (plain data, filled once per
// frame by the movie layer's CueRecorder); cue_layers.h draws them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "render/ring_buffer.h"

namespace hexgait {

struct CueOptions {
  bool footprints = false;  // a mark in the leg's colour where a foot touched down, fading
  bool trail = false;       // the body centre's path on the ground, fading
  bool swing = false;       // legs whose foot is off the ground in their leg colour
  bool strip = false;       // the footfall diagram scrolling along the bottom of the frame
  bool any() const { return footprints || trail || swing || strip; }
};

// "footprints,trail,swing,strip" in any subset and order, "all" or "none". Returns an empty
// string, or a one-line reason the text is wrong.
std::string ParseCues(const std::string& text, CueOptions* cues);
inline constexpr const char* kCueNames = "footprints,trail,swing,strip";

struct Footprint {
  Eigen::Vector2f at;  // on the ground
  float time = 0;      // of the touch-down
  int leg = 0;
};
struct TrailPoint {
  Eigen::Vector2f at;
  float time = 0;
};
struct FootfallSample {
  float time = 0;
  uint32_t feet_down = 0;  // bit i: leg i's foot touches the ground
};

// What the cues remember of one creature's run; bounded whatever the movie's length.
struct GaitHistory {
  float now = 0;             // time of the latest sample
  float cycle_period = 1;    // time units per gait cycle: fading and the strip's window
  float foot_radius = 0.1f;  // footprint size, from the creature's size
  uint32_t feet_down = 0;    // at `now`
  int num_legs = 0;
  RingBuffer<Footprint> footprints{384};  // 64 steps per leg: more than fade in a few cycles
  RingBuffer<TrailPoint> trail{1024};
  RingBuffer<FootfallSample> strip{1024};  // frames; enough for the strip's window at 240 fps
};

}  // namespace hexgait
