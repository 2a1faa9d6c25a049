#include "app/view_options.h"

#include "render/gl_context.h"

namespace hexgait {

void AddViewOptions(CLI::App* command, ViewRequest& options, bool with_cues,
                    const std::string& default_view) {
  command->add_option("--view", options.view,
                      "Camera preset: " + CameraPresetNames() + " (default " + default_view +
                          ": the legs of both sides, their lift and the ground they step on)");
  command->add_option("--camera", options.camera,
                      "Camera fields over the preset, e.g. \"eye=4,-6,2;target=0,0,-0.3;fov=35\": "
                      "eye offset from the target, target offset from the body centre, vertical "
                      "field of view in degrees (5 to 120)");
  command->add_option("--track", options.track,
                      "How the camera follows the creature: follow (eases after the body), x "
                      "(slides along x at a fixed height and distance, so speed shows against "
                      "the ground) or fixed (stays where the body started); default: the "
                      "preset's");
  if (with_cues) {
    command->add_option("--cues", options.cues,
                        std::string("Gait cues, comma-separated: ") + kCueNames +
                            " (footprints in leg colours, the body's trail, swinging legs "
                            "highlighted, a scrolling footfall strip), all or none");
  }
}

// Every command that draws takes --gl; a replay, drawn by the browser, does not.
void AddGlOption(CLI::App* command) {
  std::string backends;
  for (const std::string& name : GlBackendNames())
    backends += (backends.empty() ? "" : ", ") + name;
  command
      ->add_option_function<std::string>(
          "--gl", [](const std::string& name) { SetGlBackend(name); },
          "OpenGL backend: " + backends +
              " (default: the environment variable HEXGAIT_GL, else the first of these that "
              "works; `hexgait --version` names the one in use)")
      ->check(CLI::IsMember(GlBackendNames()));
}

}  // namespace hexgait
