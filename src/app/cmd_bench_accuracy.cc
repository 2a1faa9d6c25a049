// hexgait bench accuracy: run time against error (MeasureAccuracyToFolder, run/bench_request.h).
#include <cstdio>
#include <memory>

#include "app/bench_common.h"
#include "app/commands.h"

namespace hexgait {
namespace {

void RunAccuracy(const AccuracyRequest& request) {
  const AccuracyResult result = MeasureAccuracyToFolder(request, PrintProgressLine);
  std::printf("%s", AccuracySummary(result.report).c_str());
  std::printf("\nwrote %s\n", result.csv_path.c_str());
}

}  // namespace

void AddBenchAccuracy(CLI::App& bench) {
  auto acc = std::make_shared<AccuracyRequest>();
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
  a->add_option("--reference-tolerance", acc->reference_tolerance,
                "Absolute and relative tolerance of the reference stepper")
      ->capture_default_str();
  a->callback([acc] { RunAccuracy(*acc); });
}

}  // namespace hexgait
