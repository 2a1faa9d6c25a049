// hexgait render: one gait movie. The simulation advances one video frame's worth of steps at
// a time and the renderer draws only those frames (a few hundred, not 400,000 steps).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/movie_options.h"
#include "util/error.h"
#include "util/output.h"
#include "util/progress_bar.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct RenderOptions {
  GaitMovieFile request;
  bool json = false;
};

void Run(const RenderOptions& opt) {
  StopIsPolled();  // stops between frames, removing the unfinished movie
  const std::string& out = opt.request.out;
  ProgressBar bar("rendering " + out);
  const GaitMovieWritten written = WriteGaitMovie(opt.request, bar.Hook());
  bar.Clear();
  const MovieStats& stats = written.stats;
  const MovieSettings& settings = written.settings;
  const Scene& scene = written.scene;
  const std::string& label = written.label;
  // The run the movie shows, reported as `simulate` reports it (the same bits: one run, never
  // restarted), then the movie's own fields.
  const RunResult& result = stats.results.front();
  if (opt.json) {
    nlohmann::json j =
        RunReportJson(result, settings.run, label, scene.model, scene.program.cycle_period);
    j["path"] = out;
    j["frames"] = stats.frames;
    j["size"] = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    j["fps"] = settings.fps;
    j["wall_seconds"] = stats.seconds_total;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    PrintMovieSummary(out, stats, settings);
    PrintRunReport(result, settings.run, label, scene.model, scene.program.cycle_period);
  }
  ReportExpected(written.expected);
}

}  // namespace

void RegisterRender(CLI::App& app) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render one gait movie (H.264 in MP4)");
  AddGenomeOptions(cmd, opt->request.genome);
  cmd->add_option("--out", opt->request.out, "MP4 file to write")->capture_default_str();
  AddExpectOption(cmd, opt->request.expect);
  cmd->add_flag("--json", opt->json,
                "Print one JSON object: the run's result (the fields of simulate --json) and "
                "the movie's path, frames, size, fps and wall_seconds");
  AddMovieOptions(cmd, opt->request.movie, true);
  AddSceneOptions(cmd, opt->request.scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
