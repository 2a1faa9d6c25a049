#include "run/report_request.h"

#include <vector>

#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/run_state.h"

namespace hexgait {

int WriteReport(const ReportOptions& options) {
  IoPaths()
      .Input("--run", options.run_dir)
      .Input("--movies", options.movies_dir)
      .Input("--figures", options.figures_dir)
      .Input("--repertoire", options.repertoire_dir)
      .Input("--adapt", options.adapt_dir)
      .OutputFolder("--out", options.out_dir)
      .Check();
  RefuseUnfinishedRun(options.run_dir, "--run", "evolve");
  std::vector<FolderArg> folders = {{"--run", options.run_dir}};
  if (!options.repertoire_dir.empty()) {
    RefuseUnfinishedRun(options.repertoire_dir, "--repertoire", "repertoire");
    folders.push_back({"--repertoire", options.repertoire_dir});
  }
  if (!options.adapt_dir.empty()) folders.push_back({"--adapt", options.adapt_dir});
  // One page, one creature: a repertoire or an adaptation of another scene is refused, not
  // shown beside the run as if it were the same animal.
  SceneOfFolders(SceneOptions(), folders);
  return MakeReport(options);
}

}  // namespace hexgait
