#include "run/figures_request.h"

#include "report/gnuplot.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/run_state.h"
#include "run/sweep_summary.h"

namespace hexgait {

nlohmann::json WriteFigures(const FiguresFile& request, const LogLine& log,
                            const Progress& on_progress) {
  FiguresOptions figures = request.figures;
  figures.runs.clear();  // a sweep folder stands for its seeds' runs
  for (const std::string& dir : request.figures.runs) {
    for (const std::string& run : RunFoldersOf(dir)) figures.runs.push_back(run);
  }
  figures.figure1 = !request.no_figure1;
  figures.figure1_camera = MakeCameraSpec(request.view, "three-quarter", kStillFieldOfView);
  if (figures.figure1) {
    CheckCameraSeesCreature(figures.figure1_camera, request.view, kFigureWidth, kFigureHeight);
  }
  IoPaths paths;
  paths.Input("--run", figures.run_dir).Input("--bench", figures.bench_dir);
  for (const std::string& dir : figures.runs) paths.Input("--runs", dir);
  paths.OutputFolder("--out", figures.out_dir).Check();
  RefuseUnfinishedRun(figures.run_dir, "--run", "evolve");
  for (const std::string& dir : figures.runs) RefuseUnfinishedRun(dir, "--runs", "evolve");
  // Both programs run on the scene the run was evolved on (--runs give only their fitness).
  const SceneOptions scene_options = SceneOfFolders(request.scene, {{"--run", figures.run_dir}});
  SceneInputs(scene_options).Check();
  const RunOptions run = MakeRunOptions(scene_options, request.time, 2);  // both programs
  const Scene scene = LoadScene(scene_options);
  GenomeChoice evolved_choice;
  evolved_choice.path = figures.run_dir + "/best.genome";
  const FigurePrograms programs{scene.model,
                                scene.program,
                                LoadGenomeChoice(GenomeChoice{}, scene, nullptr),
                                LoadGenomeChoice(evolved_choice, scene, nullptr),
                                evolved_choice.path,
                                run};
  return MakeFigures(figures, programs, log, on_progress);
}

}  // namespace hexgait
