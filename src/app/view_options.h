// --view, --camera, --track (and --cues where frames follow each other): one place for the
// camera and gait-cue options `still`, `render`, `movie`, `filmstrip` and `figures` share.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "render/camera.h"
#include "render/gait_cues.h"

namespace hexgait {

// A still (Figure 1, `still`) frames the creature closer than a movie, which keeps ground
// ahead in view so the walk's speed shows.
inline constexpr float kStillFieldOfView = 24.0f;

struct ViewCliOptions {
  std::string view;    // empty: the command's default preset
  std::string camera;  // "eye=X,Y,Z;target=X,Y,Z;fov=DEG" over the preset
  std::string track;   // empty: the preset's tracking
  std::string cues;    // empty: none
};

// `with_cues` adds --cues; `default_view` names the preset --help shows.
void AddViewOptions(CLI::App* command, ViewCliOptions& options, bool with_cues,
                    const std::string& default_view = "three-quarter");
// The camera the options describe: the preset (with the command's own field of view when
// `default_fov` > 0: a still or a filmstrip frame shows the creature, not the ground ahead),
// then --camera's fields, then --track. Throws InputError with a one-line message.
CameraSpec MakeCameraSpec(const ViewCliOptions& options,
                          const std::string& default_view = "three-quarter",
                          float default_fov = 0);
CueOptions MakeCueOptions(const ViewCliOptions& options);

}  // namespace hexgait
