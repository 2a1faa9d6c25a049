#include "render/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "render/renderer.h"

namespace hexgait {
namespace {

using V = Eigen::Vector3f;
using T = CameraSpec::Tracking;

// Parses "X,Y,Z" (finite numbers); false on anything else.
bool ParseVector(const std::string& text, V* out) {
  std::stringstream in(text);
  std::string part;
  int n = 0;
  while (std::getline(in, part, ',')) {
    if (n == 3 || part.empty()) return false;
    char* end = nullptr;
    const float value = std::strtof(part.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value)) return false;
    (*out)[n++] = value;
  }
  return n == 3 && text.back() != ',';
}

}  // namespace

const std::vector<CameraPreset>& CameraPresets() {
  // Offsets are in length units around the body centre, sized for a creature about 2 long
  // whose body is 0.5 to 1 above the ground; the target sits below the body so the legs and
  // the ground they step on fill the lower half of the frame.
  static const std::vector<CameraPreset> presets = {
      {"three-quarter",
       "front-right and above, following the body: both sides' legs and their footprints",
       {V(3.2f, -6.2f, 2.3f), V(0, 0, -0.3f), 35.0f, T::kFollow}},
      {"side",
       "from the right, a little above the body, sliding along x: leg lifts and speed",
       {V(0, -7.5f, 1.5f), V(0, 0, -0.35f), 35.0f, T::kTrackX}},
      {"front",
       "from ahead, slightly to the right, following: splay and sway",
       {V(7.0f, -1.2f, 1.6f), V(0, 0, -0.3f), 32.0f, T::kFollow}},
      {"top",
       "from straight above, following: the footfall pattern on the ground",
       {V(0, 0, 9.0f), V(0, 0, -0.5f), 35.0f, T::kFollow}},
  };
  return presets;
}

const CameraPreset* FindCameraPreset(const std::string& name) {
  for (const CameraPreset& p : CameraPresets()) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

std::string CameraPresetNames() {
  std::string names;
  for (const CameraPreset& p : CameraPresets()) {
    if (!names.empty()) names += '|';
    names += p.name;
  }
  return names;
}

const char* TrackingName(T tracking) {
  switch (tracking) {
    case T::kFollow:
      return "follow";
    case T::kTrackX:
      return "x";
    case T::kFixed:
      return "fixed";
  }
  return "?";
}

bool ParseTracking(const std::string& text, T* tracking) {
  for (T t : {T::kFollow, T::kTrackX, T::kFixed}) {
    if (text == TrackingName(t)) {
      *tracking = t;
      return true;
    }
  }
  return false;
}

std::string ParseCameraSpec(const std::string& text, CameraSpec* spec) {
  CameraSpec result = *spec;
  std::stringstream in(text);
  std::string field;
  bool seen_eye = false, seen_target = false, seen_fov = false;
  while (std::getline(in, field, ';')) {
    if (field.empty()) continue;
    const size_t eq = field.find('=');
    if (eq == std::string::npos) return "'" + field + "' is not KEY=VALUE";
    const std::string key = field.substr(0, eq), value = field.substr(eq + 1);
    if (key == "eye" || key == "target") {
      bool& seen = key == "eye" ? seen_eye : seen_target;
      if (seen) return key + " given twice";
      seen = true;
      V v;
      if (!ParseVector(value, &v)) return key + " needs three numbers X,Y,Z, got '" + value + "'";
      (key == "eye" ? result.eye_offset : result.target_offset) = v;
    } else if (key == "fov") {
      if (seen_fov) return "fov given twice";
      seen_fov = true;
      char* end = nullptr;
      const float fov = std::strtof(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !(fov >= 5.0f && fov <= 120.0f)) {
        return "fov must be between 5 and 120 degrees, got '" + value + "'";
      }
      result.fov_y = fov;
    } else {
      return "unknown key '" + key + "' (use eye, target and fov)";
    }
  }
  if (!seen_eye && !seen_target && !seen_fov) return "expected eye=X,Y,Z;target=X,Y,Z;fov=DEG";
  if (result.eye_offset.norm() < 0.05f) return "eye must be away from the target";
  *spec = result;
  return "";
}

Eigen::Matrix4f ViewProjection(const CameraSpec& spec, const Eigen::Vector3f& tracked,
                               float aspect) {
  const V target = tracked + spec.target_offset;
  const V eye = target + spec.eye_offset;
  // LookAt needs an up direction not parallel to the view; straight down, +y is up on screen.
  const V direction = spec.eye_offset.normalized();
  const V up = std::abs(direction.z()) > 0.999f ? V::UnitY() : V::UnitZ();
  // The depth range follows the eye: the presets' 0.1 to 100 up to an eye 25 units away, then
  // far enough to reach past the target and the ground around it, with the near plane moved
  // out to keep the depth buffer's precision.
  const float distance = spec.eye_offset.norm() + spec.target_offset.norm();
  const float far = std::max(100.0f, 4.0f * distance);
  const float near = std::max(0.1f, far / 1000.0f);
  return Perspective(spec.fov_y, aspect, near, far) * LookAt(eye, target, up);
}

std::string CameraBlindness(const CameraSpec& spec, float aspect) {
  // The body centre at the start, in clip space: tracked at the origin, it is -target_offset
  // from the target.
  const Eigen::Vector4f clip =
      ViewProjection(spec, V::Zero(), aspect) * Eigen::Vector4f(0, 0, 0, 1);
  if (!(clip.w() > 0)) return "the creature is behind the camera";
  const Eigen::Vector3f ndc = clip.head<3>() / clip.w();
  if (std::abs(ndc.x()) > 1 || std::abs(ndc.y()) > 1) {
    return "the creature is outside the field of view (move the target nearer the body or widen "
           "fov)";
  }
  if (std::abs(ndc.z()) > 1) return "the creature is outside the depth range";
  return "";
}

const Eigen::Vector3f& CameraTracker::Update(const Eigen::Vector3f& body_centre) {
  switch (tracking_) {
    case T::kFollow:
      // A first-order follow per frame: glides with the walk instead of jittering with steps.
      current_ += 0.15f * (body_centre - current_);
      break;
    case T::kTrackX:
      current_ = V(body_centre.x(), start_.y(), start_.z());
      break;
    case T::kFixed:
      current_ = start_;
      break;
  }
  return current_;
}

}  // namespace hexgait
