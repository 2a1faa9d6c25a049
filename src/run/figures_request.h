// `hexgait figures` as one call: the figure set of an evolve run (report/figures.h), with both
// programs run on the run's own scene.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "report/figures.h"
#include "run/scene.h"
#include "run/view_request.h"

namespace hexgait {

struct FiguresFile {
  SceneOptions scene;      // flags given beside --run must agree with its record
  FiguresOptions figures;  // runs: evolve folders, or sweep folders standing for their seeds
  double time = kPaperDuration;
  bool no_figure1 = false;
  ViewRequest view;  // Figure 1's camera
};

// Every check before any work, in this order: Figure 1's camera, the inputs and the output
// folder, the run and the --runs finished, the run's scene (run/folder_scene.h), the run's
// length, both genomes; then the figures (MakeFigures, which finds gnuplot and libpng before its
// simulations). `log` gets a line per figure; `on_progress` the simulations' progress. Returns
// figures.json's content.
nlohmann::json WriteFigures(const FiguresFile& request, const LogLine& log,
                            const Progress& on_progress = {});

}  // namespace hexgait
