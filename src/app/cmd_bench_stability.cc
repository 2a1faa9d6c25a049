// hexgait bench stability: numerical stress tests (MeasureStabilityToFolder, run/bench_request.h).
#include <cstdio>
#include <memory>

#include "app/bench_common.h"
#include "app/cli_common.h"
#include "app/commands.h"

namespace hexgait {
namespace {

void RunStability(const StabilityRequest& request) {
  const StabilityResult result = MeasureStabilityToFolder(request, PrintProgressLine);
  std::printf("%s", StabilitySummary(result.report).c_str());
  std::printf("\nwrote %s and %s\n", result.stability_csv.c_str(), result.drift_csv.c_str());
}

}  // namespace

void AddBenchStability(CLI::App& bench) {
  auto stab = std::make_shared<StabilityRequest>();
  CLI::App* s = bench.add_subcommand(
      "stability",
      "Stress tests: (a) spring stiffness x1..x100 against step size, stable or diverged, per "
      "integrator (OUT/stability.csv); (b) energy drift over 1000 time units in free flight, "
      "gravity on, ground and damping off (OUT/energy_drift.csv); (c) all -8, all +7 and random "
      "genomes with euler at dt 0.0025: walked, fell or diverged, never a silent NaN");
  AddCommonOptions(s, stab->common);
  s->add_option("--genomes", stab->genomes, "Random genomes to run")->capture_default_str();
  AddSeedOption(s, stab->seed, "Seed of the random genomes");
  s->add_option("--threads", stab->threads, "Threads for the genome runs (0: all cores)")
      ->capture_default_str();
  s->callback([stab] { RunStability(*stab); });
}

}  // namespace hexgait
