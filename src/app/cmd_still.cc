// hexgait still: one rendered frame as a PNG; by default the paper's Figure 1.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "movie/panel_view.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "render/scene.h"
#include "sim/evaluate.h"
#include "sim/run.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {

namespace {

struct StillOptions {
  SceneOptions scene;
  GenomeChoice genome;
  ViewCliOptions view;
  double time = 0;
  std::string out = "out/figure1.png";
  std::string size = "1280x720";
  bool no_overlay = false;
  bool no_shadow = false;
  int msaa = 0;
};

// The frame `opt` describes; `label` gets the program's name. Checks every option but --out.
Image RenderStill(const StillOptions& opt, std::string* label) {
  int width = 0, height = 0;
  ParseSize(opt.size, &width, &height);
  if (!(opt.time >= 0) || opt.time > 1e6) throw InputError("--time must be between 0 and 1e6");
  const CameraSpec camera = MakeCameraSpec(opt.view, "three-quarter", kStillFieldOfView);
  const CueOptions cues = MakeCueOptions(opt.view);
  SceneInputs(opt.scene, &opt.genome).Check();
  const Scene scene = LoadScene(opt.scene);
  const Genome genome = LoadGenomeChoice(opt.genome, scene, label);
  SimState state = MakeRestState(scene.model);
  // The camera and cues are sampled as a movie's frames would be, so the still matches the
  // movie's frame at that time (footprints of the last cycles, a camera easing after the body).
  PanelView view(scene.model, scene.program.cycle_period, state, camera, cues);
  view.Sample(state);
  if (opt.time > 0) {
    const RunOptions run = MakeRunOptions(opt.scene, opt.time);
    MotorController controller(scene.model, scene.program,
                               PerturbedRestLengths(scene.model, scene.program, genome), run.dt);
    PanelViewSampler sampler(view, DefaultSampleSteps(scene.program.cycle_period, run.dt));
    const RunResult result = Simulate(scene.model, controller, state, run, sampler);
    if (result.diverged) {
      throw InputError(DivergenceMessage(
          result, run, LargestStableStep(scene.model, scene.program, genome, run)));
    }
    view.Sample(state);
  }
  const auto context = GlContext::CreateOrThrow("cannot render");
  if (opt.msaa != 0 && opt.msaa != 2 && opt.msaa != 4 && opt.msaa != 8) {
    throw InputError("--msaa must be 0, 2, 4 or 8");
  }
  std::string error;
  const auto renderer = Renderer::Create(width, height, opt.msaa, &error);
  if (!renderer) throw SystemError("cannot render: " + error);
  SceneLook look;
  look.overlay = !opt.no_overlay;
  look.shadow = !opt.no_shadow;
  Image image =
      renderer->Render(view.Meshes(state, look),
                       view.ViewProjection(static_cast<float>(width) / height), look.lighting);
  const auto strip_font = MakeStripFont(cues, height, "");
  view.DrawOverlays(image, strip_font.get());
  return image;
}

void Run(const StillOptions& opt) {
  SceneInputs(opt.scene, &opt.genome).Output("--out", opt.out).Check();
  CheckExtension(opt.out, ".png", "--out");
  CheckOutputPath(opt.out, "--out");
  std::string label;
  const Image image = RenderStill(opt, &label);
  WritePng(opt.out, image);
  std::printf("wrote %s (%dx%d, %s at t = %g)\n", opt.out.c_str(), image.width, image.height,
              label.c_str(), opt.time);
}

// Every option of `still` but --out.
CLI::App* AddStill(CLI::App& app, StillOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "still", "Render one frame as a PNG (default: the paper's Figure 1, the creature at rest)");
  AddGenomeOptions(cmd, opt.genome);
  cmd->add_option("--time", opt.time, "Simulated time of the frame (0: the rest pose)")
      ->capture_default_str();
  cmd->add_option("--size", opt.size, "Image size, WIDTHxHEIGHT")->capture_default_str();
  cmd->add_flag("--no-overlay", opt.no_overlay,
                "Hide the springs and particles drawn over the polygons");
  cmd->add_flag("--no-shadow", opt.no_shadow, "Do not draw the shadow on the ground");
  cmd->add_option("--msaa", opt.msaa, "Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8")
      ->capture_default_str();
  AddViewOptions(cmd, opt.view, true);
  AddSceneOptions(cmd, opt.scene);
  return cmd;
}

}  // namespace

void RegisterStill(CLI::App& app) {
  auto opt = std::make_shared<StillOptions>();
  CLI::App* cmd = AddStill(app, *opt);
  cmd->add_option("--out", opt->out, "PNG file to write")->capture_default_str();
  cmd->callback([opt] { Run(*opt); });
}

void RegisterStillToImage(CLI::App& app, Image* image) {
  auto opt = std::make_shared<StillOptions>();
  AddStill(app, *opt)->callback([opt, image] {
    std::string label;
    *image = RenderStill(*opt, &label);
  });
}

}  // namespace hexgait
