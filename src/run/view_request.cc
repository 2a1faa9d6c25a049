#include "run/view_request.h"

#include <charconv>

#include "util/error.h"

namespace hexgait {

CameraSpec MakeCameraSpec(const ViewRequest& request, const std::string& default_view,
                          float default_fov) {
  const std::string name = request.view.empty() ? default_view : request.view;
  const CameraPreset* preset = FindCameraPreset(name);
  if (!preset) {
    throw InputError("--view '" + name + "': unknown view (use " + CameraPresetNames() + ")");
  }
  CameraSpec spec = preset->spec;
  if (default_fov > 0) spec.fov_y = default_fov;
  if (!request.camera.empty()) {
    const std::string error = ParseCameraSpec(request.camera, &spec);
    if (!error.empty()) throw InputError("--camera '" + request.camera + "': " + error);
  }
  if (!request.track.empty() && !ParseTracking(request.track, &spec.tracking)) {
    throw InputError("--track '" + request.track + "': use follow, x or fixed");
  }
  return spec;
}

void CheckCameraSeesCreature(const CameraSpec& camera, const ViewRequest& request, int width,
                             int height) {
  const std::string why =
      CameraBlindness(camera, static_cast<float>(width) / static_cast<float>(height));
  if (why.empty()) return;
  std::string what = request.camera.empty() ? "--view '" + request.view + "'"
                                            : "--camera '" + request.camera + "'";
  throw InputError(what + ": the frame would show nothing: " + why);
}

CueOptions MakeCueOptions(const ViewRequest& request, const std::string& flag) {
  CueOptions cues;
  if (request.cues.empty()) return cues;
  const std::string error = ParseCues(request.cues, &cues);
  if (!error.empty()) throw InputError(flag + " '" + request.cues + "': " + error);
  return cues;
}

void ParseSize(const std::string& text, int* width, int* height, const std::string& flag) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto w = std::from_chars(begin, end, *width);
  const bool ok_w = w.ec == std::errc() && w.ptr != begin && w.ptr < end && *w.ptr == 'x';
  const auto h = ok_w ? std::from_chars(w.ptr + 1, end, *height) : w;
  if (!ok_w || h.ec != std::errc() || h.ptr != end || h.ptr == w.ptr + 1) {
    throw InputError(flag + " '" + text + "': expected WIDTHxHEIGHT, for example 1280x720");
  }
  if (*width < 16 || *height < 16 || *width > 7680 || *height > 4320) {
    throw InputError(flag + " '" + text + "': each side must be between 16 and 7680x4320");
  }
}

void CheckMsaa(int samples) {
  if (samples != 0 && samples != 2 && samples != 4 && samples != 8) {
    throw InputError("--msaa must be 0, 2, 4 or 8");
  }
}

}  // namespace hexgait
