// Writes a replay as one self-contained HTML page: the page template, its script and style
// (assets/replay/, embedded in the binary), the project's own shaders (shaders/, which the
// page compiles as WebGL2's GLSL ES 3.00), and the run as JSON with its frames in base64.
// Nothing on the page is fetched from anywhere.
#pragma once

#include <string>

#include "model/creature.h"
#include "render/camera.h"
#include "render/gait_cues.h"
#include "render/meshes.h"
#include "replay/replay_recording.h"

namespace hexgait {

struct ReplayPageOptions {
  std::string title;    // what is replayed, e.g. "evolved genome (best.genome)"
  std::string summary;  // one line of facts about the run, shown under the title
  double cycle_period = 66;
  double duration = 0;  // the run's simulated time
  double dt = 0;
  std::string view = "three-quarter";  // the preset the page opens with
  CameraSpec camera;                   // that preset with the command's --camera and --track
  float preset_fov = 0;                // field of view of every preset button (0: the preset's)
  CueOptions cues;                     // which cues are on when the page opens
  MeshStyle look;
};

std::string ReplayPage(const CreatureModel& model, const ReplayRecording& recording,
                       const ReplayPageOptions& options);

// Standard base64 (RFC 4648) of `size` bytes: how the frames travel inside the page.
std::string Base64(const void* data, size_t size);

}  // namespace hexgait
