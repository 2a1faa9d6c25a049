// hexgait bench stability: numerical stress tests (the work is in src/bench/stability.h).
#include <algorithm>
#include <cstdio>
#include <memory>

#include "app/bench_common.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "bench/stability.h"
#include "motor/assets.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct StabilityFlags {
  BenchCommon common;
  int genomes = 1000;
  uint64_t seed = 1;
  int threads = 0;
};

void RunStability(const StabilityFlags& f) {
  StabilityOptions options;
  options.integrators = ParseIntegratorList(f.common.integrators);
  if (f.genomes < 0 || f.genomes > 1000000) throw InputError("--genomes must be in [0, 1000000]");
  if (f.threads < 0 || f.threads > 1024) throw InputError("--threads must be in [0, 1024]");
  options.random_genomes = f.genomes;
  options.seed = f.seed;
  options.threads = f.threads;
  if (f.common.quick) {
    options.stiffness_multipliers = {1, 10, 100};
    options.steps = {0.02, 0.005, 0.00125};
    options.map_duration = 5;
    options.drift_duration = 50;
    options.random_genomes = std::min(options.random_genomes, 4);
  }
  const CreatureModel model = LoadCreatureOrDefault(f.common.creature);
  const MotorProgram program = LoadMotorProgramOrDefault("", model, f.common.creature);
  BenchOutDir out(f.common.out_dir, "stability.csv");
  const std::string& dir = out.path();
  const StabilityReport report = RunStabilityBench(model, program, options, PrintProgressLine);
  WriteFileAtomically(dir + "stability.csv", StabilityCsv(report));
  WriteFileAtomically(dir + "energy_drift.csv", EnergyDriftCsv(report));
  out.Keep();
  std::printf("%s", StabilitySummary(report).c_str());
  std::printf("\nwrote %sstability.csv and %senergy_drift.csv\n", dir.c_str(), dir.c_str());
}

}  // namespace

void AddBenchStability(CLI::App& bench) {
  auto stab = std::make_shared<StabilityFlags>();
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
