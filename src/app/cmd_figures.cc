// hexgait figures: the figure set for reports (src/report/figures.h), from an evolve run.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "run/figures_request.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

void Run(const FiguresFile& opt) {
  ProgressBar bar("simulating both programs");
  const nlohmann::json manifest = WriteFigures(
      opt,
      [&bar](const std::string& line) {
        bar.Clear();
        std::printf("  %s\n", line.c_str());
        std::fflush(stdout);
      },
      bar.Hook());
  bar.Clear();
  std::printf("wrote %zu figures to %s/ in %.1f s\n", manifest["figures"].size(),
              opt.figures.out_dir.c_str(), manifest["wall_seconds"].get<double>());
}

}  // namespace

void RegisterFigures(CLI::App& app) {
  auto opt = std::make_shared<FiguresFile>();
  CLI::App* cmd = app.add_subcommand(
      "figures",
      "Draw the figures for a report (PNG, SVG, the CSV behind each and its gnuplot script)");
  FiguresOptions& f = opt->figures;
  cmd->add_option("--run", f.run_dir, "'hexgait evolve' folder: fitness.csv, run.json, best.genome")
      ->capture_default_str();
  cmd->add_option(
      "--runs", f.runs,
      "More evolve folders (seeds), or a sweep folder: adds the median and range of their "
      "best fitness");
  cmd->add_option("--bench", f.bench_dir,
                  "Folder with accuracy.csv and stability.csv ('hexgait bench'); skipped if absent")
      ->capture_default_str();
  cmd->add_option("--out", f.out_dir, "Folder to write (replaced whole)")->capture_default_str();
  cmd->add_option("--time", opt->time, "Simulated time for the gait, body and path figures")
      ->capture_default_str();
  cmd->add_option("--gait-cycles", f.gait_cycles, "Gait cycles shown in the gait diagram")
      ->capture_default_str();
  AddViewOptions(cmd, opt->view, false);
  AddGlOption(cmd);
  cmd->add_flag("--no-figure1", opt->no_figure1,
                "Skip Figure 1 (the only figure that needs an OpenGL context)");
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
