// What a picture shows, as its options name it: the frame size, the camera (a preset, fields
// over it, how it follows the creature) and the gait cues. `still`, `render`, `movie`,
// `filmstrip`, `figures` and the Python module's stills and movies parse them here, with one
// message for each mistake.
#pragma once

#include <string>

#include "render/camera.h"
#include "render/gait_cues.h"

namespace hexgait {

// A still (Figure 1, `still`) frames the creature closer than a movie, which keeps ground
// ahead in view so the walk's speed shows.
inline constexpr float kStillFieldOfView = 24.0f;

struct ViewRequest {
  std::string view;    // empty: the command's default preset
  std::string camera;  // "eye=X,Y,Z;target=X,Y,Z;fov=DEG" over the preset
  std::string track;   // empty: the preset's tracking
  std::string cues;    // empty: none
};

// The camera the request describes: the preset (with the command's own field of view when
// `default_fov` > 0: a still or a filmstrip frame shows the creature, not the ground ahead),
// then --camera's fields, then --track. Throws InputError with a one-line message.
CameraSpec MakeCameraSpec(const ViewRequest& request,
                          const std::string& default_view = "three-quarter", float default_fov = 0);
// Throws InputError when the camera shows nothing of the creature in a frame of width x height
// (render/camera.h, CameraBlindness), naming the options that set it.
void CheckCameraSeesCreature(const CameraSpec& camera, const ViewRequest& request, int width,
                             int height);
// `flag` names the option in messages.
CueOptions MakeCueOptions(const ViewRequest& request, const std::string& flag = "--cues");

// "WxH", each side from 16 to 7680 (width) and 4320 (height); throws InputError.
void ParseSize(const std::string& text, int* width, int* height,
               const std::string& flag = "--size");

// Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8; throws InputError otherwise.
void CheckMsaa(int samples);

}  // namespace hexgait
