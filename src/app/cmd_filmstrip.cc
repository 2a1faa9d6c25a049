// hexgait filmstrip: frames across one gait cycle side by side in one PNG (movie/filmstrip.h).
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "ga/genome_eval.h"
#include "motor/leg_targets.h"
#include "movie/filmstrip.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct FilmstripOptions {
  SceneOptions scene;
  GenomeChoice genome;
  ViewRequest view;
  int cycle = 3;
  int frames = 6;
  std::string size = "400x300";
  int msaa = 4;
  bool no_shadow = false;
  std::string out = "out/filmstrip.png";
};

// A paper's filmstrip: every frame from the same three-quarter view (both sides' legs), the
// camera sliding along x so progress shows against the ground, lifted legs in their colours
// and footprints so each frame's stance can be read.
constexpr const char* kDefaultView = "three-quarter";
constexpr const char* kDefaultCues = "footprints,swing";
constexpr float kDefaultFov = 28.0f;

void Run(const FilmstripOptions& opt) {
  FilmstripSettings settings;
  ParseSize(opt.size, &settings.frame_width, &settings.frame_height);
  if (opt.frames < 2 || opt.frames > 24) throw InputError("--frames must be between 2 and 24");
  if (opt.cycle < 1 || opt.cycle > 10000) throw InputError("--cycle must be between 1 and 10000");
  if (static_cast<long long>(settings.frame_width) * opt.frames > 16384) {
    throw InputError("--frames x width must be at most 16384 pixels");
  }
  CheckMsaa(opt.msaa);
  // Small frames side by side: zoomed in so the legs read (--camera fov=... overrides it).
  settings.camera = MakeCameraSpec(opt.view, kDefaultView, kDefaultFov);
  if (opt.view.track.empty()) settings.camera.tracking = CameraSpec::Tracking::kTrackX;
  ViewRequest view = opt.view;
  if (view.cues.empty()) view.cues = kDefaultCues;
  settings.cues = MakeCueOptions(view);
  SceneInputs(opt.scene, &opt.genome).Output("--out", opt.out).Check();
  CheckExtension(opt.out, ".png", "--out");
  CheckOutputPath(opt.out, "--out");
  const Scene scene = LoadScene(opt.scene);
  settings.run = MakeRunOptions(opt.scene, opt.cycle * scene.program.cycle_period);
  settings.frames = opt.frames;
  settings.cycle = opt.cycle;
  settings.msaa_samples = std::max(1, opt.msaa);
  settings.look.overlay = false;
  settings.look.shadow = !opt.no_shadow;
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  const auto context = GlContext::CreateOrThrow("cannot render");
  const FilmstripResult result =
      MakeFilmstrip(scene.model, scene.program,
                    PerturbedRestLengths(scene.model, scene.program, genome), settings);
  WritePng(opt.out, result.image);
  std::printf("wrote %s (%dx%d, %s, gait cycle %d in %d frames%s)\n", opt.out.c_str(),
              result.image.width, result.image.height, label.c_str(), opt.cycle, opt.frames,
              result.run.fell ? ", fallen" : "");
}

}  // namespace

void RegisterFilmstrip(CLI::App& app) {
  auto opt = std::make_shared<FilmstripOptions>();
  CLI::App* cmd = app.add_subcommand(
      "filmstrip",
      "Render frames across one gait cycle side by side in one PNG (a locomotion paper's figure)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--cycle", opt->cycle, "Gait cycle shown (1 is the first)")
      ->capture_default_str();
  cmd->add_option("--frames", opt->frames, "Frames across the cycle (2 to 24)")
      ->capture_default_str();
  cmd->add_option("--size", opt->size, "Size of each frame, WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--msaa", opt->msaa, "Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8")
      ->capture_default_str();
  cmd->add_flag("--no-shadow", opt->no_shadow, "Do not draw the shadow on the ground");
  cmd->add_option("--out", opt->out, "PNG file to write")->capture_default_str();
  AddViewOptions(cmd, opt->view, true, kDefaultView);
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
