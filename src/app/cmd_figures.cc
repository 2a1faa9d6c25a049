// hexgait figures: the figure set for reports (src/report/figures.h), from an evolve run.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "report/figures.h"
#include "report/gnuplot.h"
#include "run/folder_scene.h"
#include "run/run_state.h"
#include "run/sweep_summary.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

struct FiguresCommandOptions {
  SceneOptions scene;
  FiguresOptions figures;
  double time = kPaperDuration;
  bool no_figure1 = false;
  ViewRequest view;  // Figure 1's camera
};

void Run(const FiguresCommandOptions& opt) {
  FiguresOptions figures = opt.figures;
  figures.runs.clear();  // a sweep folder stands for its seeds' runs
  for (const std::string& dir : opt.figures.runs) {
    for (const std::string& run : RunFoldersOf(dir)) figures.runs.push_back(run);
  }
  figures.figure1 = !opt.no_figure1;
  figures.figure1_camera = MakeCameraSpec(opt.view, "three-quarter", kStillFieldOfView);
  if (figures.figure1) {
    CheckCameraSeesCreature(figures.figure1_camera, opt.view, kFigureWidth, kFigureHeight);
  }
  IoPaths paths;
  paths.Input("--run", figures.run_dir).Input("--bench", figures.bench_dir);
  for (const std::string& dir : figures.runs) paths.Input("--runs", dir);
  paths.OutputFolder("--out", figures.out_dir).Check();
  RefuseUnfinishedRun(figures.run_dir, "--run");
  for (const std::string& dir : figures.runs) RefuseUnfinishedRun(dir, "--runs");
  // Both programs run on the scene the run was evolved on (--runs give only their fitness).
  const SceneOptions scene_options = SceneOfFolders(opt.scene, {{"--run", figures.run_dir}});
  SceneInputs(scene_options).Check();
  const RunOptions run = MakeRunOptions(scene_options, opt.time, 2);  // both programs
  const Scene scene = LoadScene(scene_options);
  GenomeChoice evolved_choice;
  evolved_choice.path = figures.run_dir + "/best.genome";
  FigurePrograms programs{scene.model,
                          scene.program,
                          LoadGenomeChoice(GenomeChoice{}, scene, nullptr),
                          LoadGenomeChoice(evolved_choice, scene, nullptr),
                          evolved_choice.path,
                          run};
  std::printf("figures: %s -> %s\n", figures.run_dir.c_str(), figures.out_dir.c_str());
  std::fflush(stdout);
  ProgressBar bar("simulating both programs");
  const nlohmann::json manifest = MakeFigures(
      figures, programs,
      [&bar](const std::string& line) {
        bar.Clear();
        std::printf("  %s\n", line.c_str());
        std::fflush(stdout);
      },
      [&bar](double fraction) { bar.Update(fraction); });
  bar.Clear();
  std::printf("wrote %zu figures to %s/ in %.1f s\n", manifest["figures"].size(),
              figures.out_dir.c_str(), manifest["wall_seconds"].get<double>());
}

}  // namespace

void RegisterFigures(CLI::App& app) {
  auto opt = std::make_shared<FiguresCommandOptions>();
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
