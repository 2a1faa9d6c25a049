// hexgait render: one gait movie. The simulation advances one video frame's worth of steps at
// a time and the renderer draws only those frames (a few hundred, not 400,000 steps).
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/movie_options.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "sim/evaluate.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct RenderOptions {
  SceneOptions scene;
  GenomeChoice genome;
  MovieCliOptions movie;
  std::string out = "out/gait.mp4";
};

void Run(const RenderOptions& opt) {
  const MovieSettings settings = MakeMovieSettings(opt.movie, opt.scene);
  CheckOutputPath(opt.out, "--out");
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  std::string error;
  const auto context = GlContext::Create(&error);
  if (!context) throw InputError("cannot render: " + error);
  const MoviePanel panel{label, PerturbedRestLengths(scene.model, scene.program, genome)};
  try {
    WriteMovie(opt.out, scene, {panel}, settings, opt.movie.frames_dir);
  } catch (const MovieDiverged& e) {
    throw InputError(
        DivergenceMessage(e.result(), settings.run,
                          LargestStableStep(scene.model, scene.program, genome, settings.run)) +
        "; no movie written");
  }
}

}  // namespace

void RegisterRender(CLI::App& app) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render one gait movie (H.264 in MP4)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--out", opt->out, "MP4 file to write")->capture_default_str();
  AddMovieOptions(cmd, opt->movie, true);
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
