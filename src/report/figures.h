// 'hexgait figures': every figure of the experiment as PNG + SVG + the CSV it plots + the
// gnuplot script that draws it, written whole into one folder, with a manifest (figures.json)
// that 'hexgait report' reads.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "render/camera.h"
#include "sim/step_loop.h"
#include "util/progress.h"

namespace hexgait {

struct FiguresOptions {
  std::string run_dir = "out/run";      // an 'hexgait evolve' folder: fitness.csv, run.json
  std::vector<std::string> runs;        // more evolve folders (seeds) for the median-and-band plot
  std::string bench_dir = "out/bench";  // accuracy.csv and stability.csv, if there
  std::string out_dir = "out/figures";
  int gait_cycles = 5;           // gait diagram window
  double sample_interval = 0.1;  // trace sampling (time units); body and path CSVs use every
  int curve_stride = 5;          // curve_stride-th sample (0.5 time units)
  bool figure1 = true;           // needs an OpenGL (OSMesa) context
  CameraSpec figure1_camera;     // the view of Figure 1 (--view, --camera, --track)
};

// What the figures simulate: the scene, the two programs and the run (--time, --dt, ...).
struct FigurePrograms {
  const CreatureModel& model;
  const MotorProgram& program;
  Genome unoptimized;
  Genome evolved;
  std::string evolved_source;  // the genome file, for captions
  RunOptions run;
};

// Writes the figures into options.out_dir (replaced whole); returns the manifest it wrote.
// `log` receives one progress line per figure; `progress`, if given, the steps of both programs'
// simulations done of all, every 2^16 steps. Throws InputError.
nlohmann::json MakeFigures(const FiguresOptions& options, const FigurePrograms& programs,
                           const LogLine& log, const Progress& progress = {});

// The manifest's file name inside the figures folder, and the marker AtomicDir leaves there.
inline constexpr const char* kFiguresManifest = "figures.json";
inline constexpr const char* kFiguresMarker = ".hexgait-figures";

}  // namespace hexgait
