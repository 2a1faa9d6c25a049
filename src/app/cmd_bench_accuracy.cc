// hexgait bench accuracy: run time against error (the work is in src/bench/accuracy.h).
#include <algorithm>
#include <cstdio>
#include <memory>

#include "app/bench_common.h"
#include "app/commands.h"
#include "bench/accuracy.h"
#include "ga/evolution.h"
#include "ga/genome_io.h"
#include "motor/assets.h"
#include "run/io_paths.h"
#include "search/ga_optimizer.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct AccuracyFlags {
  BenchCommon common;
  std::string genome_path;
  bool full = false;
  double tolerance = 1e-10;
};

void RunAccuracy(const AccuracyFlags& f) {
  IoPaths()
      .Input("--genome", f.genome_path)
      .Output("--out", f.common.out_dir + "/accuracy.csv")
      .Check();
  AccuracyOptions options;
  options.integrators = ParseIntegratorList(f.common.integrators);
  if (!(f.tolerance > 0 && f.tolerance < 1e-3))
    throw InputError("--reference-tolerance must be in (0, 1e-3)");
  options.reference_tolerance = f.tolerance;
  options.steps = DefaultStepLadder();
  if (f.full) options.implicit_min_dt = 0;
  const CreatureModel model = LoadCreatureOrDefault(f.common.creature);
  const MotorProgram program = LoadMotorProgramOrDefault("", model, f.common.creature);
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<AccuracyProgram> programs = {{"unoptimized", Genome(layout)}};
  if (f.common.quick) {
    // One program, three steps, just past the first gait cycle.
    options.steps = {0.01, 0.005, 0.0025};
    options.duration = program.cycle_period + 4;
    options.reference_tolerance = std::max(options.reference_tolerance, 1e-8);
  }
  if (!f.genome_path.empty()) {
    programs.push_back({"evolved", LoadGenomeFile(f.genome_path, layout)});
  } else if (!f.common.quick) {
    PrintProgressLine(
        "evolving the 'evolved' program: hexgait evolve --seed 1 (the paper's settings)");
    EvolutionParams params;
    params.seed = 1;
    programs.push_back({"evolved", Evolve(model, program, params, {}).best->genome});
  }
  BenchOutDir out(f.common.out_dir, "accuracy.csv");
  const std::string& dir = out.path();
  const AccuracyReport report =
      RunAccuracyBench(model, program, programs, options, PrintProgressLine);
  WriteFileAtomically(dir + "accuracy.csv", AccuracyCsv(report));
  out.Keep();
  std::printf("%s", AccuracySummary(report).c_str());
  std::printf("\nwrote %saccuracy.csv\n", dir.c_str());
}

}  // namespace

void AddBenchAccuracy(CLI::App& bench) {
  auto acc = std::make_shared<AccuracyFlags>();
  CLI::App* a = bench.add_subcommand(
      "accuracy",
      "Every integrator on a ladder of steps (0.01 down to 0.0025/16) for the unoptimised and an "
      "evolved program: position error against an adaptive Dormand-Prince reference at t = 10 "
      "and at the end of the first gait cycle, relative error of the 1000-time-unit fitness, "
      "and the seconds of one core per 1000 time units. Prints a table; writes OUT/accuracy.csv");
  AddCommonOptions(a, acc->common);
  a->add_option("--genome", acc->genome_path,
                "The 'evolved' program (default: evolve one with seed 1 and the paper's settings)");
  a->add_flag("--full", acc->full,
              "Run implicit-euler on the whole ladder too (by default it stops at dt 0.0025: "
              "each of its steps costs a 42x42 LU factorisation)");
  a->add_option("--reference-tolerance", acc->tolerance,
                "Absolute and relative tolerance of the reference stepper")
      ->capture_default_str();
  a->callback([acc] { RunAccuracy(*acc); });
}

}  // namespace hexgait
