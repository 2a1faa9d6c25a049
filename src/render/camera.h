// A camera is data: where the eye sits relative to what it looks at, the field of view, and how
// it follows the creature (MuJoCo's camera modes). Presets are rows of one table; `--camera`
// overrides fields of a preset. The renderer only ever sees the view-projection matrix.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace hexgait {

struct CameraSpec {
  // kFollow: the target eases after the body centre (smooth, no jitter from the gait).
  // kTrackX: the target's x is the body's x; its y and z stay where they started, so the camera
  //          slides along the walking direction at a fixed height and the ground shows speed.
  // kFixed:  the target stays where the body started.
  enum class Tracking { kFollow, kTrackX, kFixed };
  // The defaults are the three-quarter preset's.
  Eigen::Vector3f eye_offset = Eigen::Vector3f(3.2f, -6.2f, 2.3f);     // eye minus target
  Eigen::Vector3f target_offset = Eigen::Vector3f(0.0f, 0.0f, -0.3f);  // target minus tracked
  float fov_y = 35.0f;                                                 // vertical, degrees
  Tracking tracking = Tracking::kFollow;
};

struct CameraPreset {
  const char* name;
  const char* description;
  CameraSpec spec;
};

// Every named view, the default first.
const std::vector<CameraPreset>& CameraPresets();
// nullptr if there is no preset of that name.
const CameraPreset* FindCameraPreset(const std::string& name);
// "three-quarter|side|front|top", for help texts and errors.
std::string CameraPresetNames();

const char* TrackingName(CameraSpec::Tracking tracking);  // "follow", "x", "fixed"
// Returns false for anything but follow, x or fixed.
bool ParseTracking(const std::string& text, CameraSpec::Tracking* tracking);

// Overrides fields of `spec` from "eye=X,Y,Z;target=X,Y,Z;fov=DEG" (any subset, any order;
// eye is the eye's offset from the target, target the target's offset from the body centre).
// Returns an empty string, or a one-line reason the text is wrong.
std::string ParseCameraSpec(const std::string& text, CameraSpec* spec);

// Projection times view for a camera looking at `tracked + spec.target_offset`; a camera
// looking straight down takes +y as its up direction.
Eigen::Matrix4f ViewProjection(const CameraSpec& spec, const Eigen::Vector3f& tracked,
                               float aspect);

// Empty, or why a camera of `spec` shows nothing of the creature in a frame of `aspect`
// (width / height): the point it tracks at the start (the body centre, offset by the target) is
// behind the eye or outside the field of view. The depth range follows the eye's distance
// (ViewProjection), so distance alone never hides it.
std::string CameraBlindness(const CameraSpec& spec, float aspect);

// Per panel, per frame: turns the body centre into the point the camera tracks, by the mode.
class CameraTracker {
 public:
  CameraTracker(CameraSpec::Tracking tracking, const Eigen::Vector3f& start)
      : tracking_(tracking), start_(start), current_(start) {}
  // Call once per frame, in frame order.
  const Eigen::Vector3f& Update(const Eigen::Vector3f& body_centre);
  const Eigen::Vector3f& current() const { return current_; }

 private:
  CameraSpec::Tracking tracking_;
  Eigen::Vector3f start_, current_;
};

}  // namespace hexgait
