// hexgait render: one gait movie. The simulation advances one video frame's worth of steps at
// a time and the renderer draws only those frames (a few hundred, not 400,000 steps).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/movie_options.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/progress_bar.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct RenderOptions {
  SceneOptions scene;
  GenomeChoice genome;
  MovieRequest movie;
  std::string out = "out/gait.mp4";
  bool json = false;
};

void Run(const RenderOptions& opt) {
  StopIsPolled();  // stops between frames, removing the unfinished movie
  const MovieSettings settings = MakeMovieSettings(opt.movie, opt.scene);
  SceneInputs(opt.scene, &opt.genome).Output("--out", opt.out).Check();
  CheckExtension(opt.out, ".mp4", "--out");
  CheckOutputPath(opt.out, "--out");
  const Scene scene = LoadScene(opt.scene);
  RefuseLongMovieSettings(opt.movie, settings, scene.program.cycle_period, opt.scene.allow_long);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  ProgressBar bar("rendering " + opt.out);
  const MovieStats stats = RenderGaitMovie(
      opt.out, scene, genome, label, settings, opt.movie.frames_dir,
      [&bar](long long frame, long long total) { bar.Count(frame, total, "frames"); });
  bar.Clear();
  // The run the movie shows, reported as `simulate` reports it (the same bits: one run, never
  // restarted), then the movie's own fields.
  const RunResult& result = stats.results.front();
  if (opt.json) {
    nlohmann::json j =
        RunReportJson(result, settings.run, label, scene.model, scene.program.cycle_period);
    j["path"] = opt.out;
    j["frames"] = stats.frames;
    j["size"] = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    j["fps"] = settings.fps;
    j["wall_seconds"] = stats.seconds_total;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    PrintMovieSummary(opt.out, stats, settings);
    PrintRunReport(result, settings.run, label, scene.model, scene.program.cycle_period);
  }
}

}  // namespace

void RegisterRender(CLI::App& app) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render one gait movie (H.264 in MP4)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--out", opt->out, "MP4 file to write")->capture_default_str();
  cmd->add_flag("--json", opt->json,
                "Print one JSON object: the run's result (the fields of simulate --json) and "
                "the movie's path, frames, size, fps and wall_seconds");
  AddMovieOptions(cmd, opt->movie, true);
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
