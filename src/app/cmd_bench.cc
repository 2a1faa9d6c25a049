// hexgait bench accuracy | stability: run time against error, and numerical stress tests.
// The work itself lives in src/bench/; this file parses flags, prints and writes the files.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "app/assets.h"
#include "app/commands.h"
#include "bench/accuracy.h"
#include "bench/stability.h"
#include "ga/evolution.h"
#include "ga/genome_io.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct BenchCommon {
  std::string out_dir = "out/bench";
  bool quick = false;
  std::string integrators;  // comma-separated; empty: all
};

struct AccuracyFlags {
  BenchCommon common;
  std::string genome_path;
  bool full = false;
  double tolerance = 1e-10;
};

struct StabilityFlags {
  BenchCommon common;
  int genomes = 1000;
  uint64_t seed = 1;
  int threads = 0;
};

void AddCommonOptions(CLI::App* cmd, BenchCommon& c) {
  cmd->add_option("--out", c.out_dir, "Folder for the CSV files")->capture_default_str();
  cmd->add_flag("--quick", c.quick, "A small version for tests: few steps, short runs");
  cmd->add_option("--integrators", c.integrators,
                  "Comma-separated integrators to run (default: all of euler, symplectic-euler, "
                  "verlet, rk4, implicit-euler)");
}

std::vector<IntegratorKind> ParseIntegratorList(const std::string& text) {
  if (text.empty()) return AllIntegrators();
  std::vector<IntegratorKind> kinds;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) kinds.push_back(ParseIntegrator(name));
  if (kinds.empty()) throw InputError("--integrators: no integrator named");
  return kinds;
}

// Creates the output folder and checks a file can be written there, before any work starts.
std::string PrepareOutDir(const std::string& out_dir, const char* first_file) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw InputError("--out '" + out_dir + "': cannot create folder" +
                     (ec ? ": " + ec.message() : ""));
  }
  const std::string dir = out_dir + "/";
  CheckOutputPath(dir + first_file, "--out");
  return dir;
}

void Progress(const std::string& line) {
  std::fprintf(stderr, "bench: %s\n", line.c_str());
}

void RunAccuracy(const AccuracyFlags& f) {
  AccuracyOptions options;
  options.integrators = ParseIntegratorList(f.common.integrators);
  if (!(f.tolerance > 0 && f.tolerance < 1e-3))
    throw InputError("--reference-tolerance must be in (0, 1e-3)");
  options.reference_tolerance = f.tolerance;
  options.steps = DefaultStepLadder();
  if (f.full) options.implicit_min_dt = 0;
  const CreatureModel model = LoadCreatureOrDefault("");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
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
    Progress("evolving the 'evolved' program: hexgait evolve --seed 1 (the paper's settings)");
    EvolutionParams params;
    params.seed = 1;
    programs.push_back({"evolved", Evolve(model, program, params, {}).best->genome});
  }
  const std::string dir = PrepareOutDir(f.common.out_dir, "accuracy.csv");
  const AccuracyReport report = RunAccuracyBench(model, program, programs, options, Progress);
  WriteFileAtomically(dir + "accuracy.csv", AccuracyCsv(report));
  std::printf("%s", AccuracySummary(report).c_str());
  std::printf("\nwrote %saccuracy.csv\n", dir.c_str());
}

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
  const CreatureModel model = LoadCreatureOrDefault("");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const std::string dir = PrepareOutDir(f.common.out_dir, "stability.csv");
  const StabilityReport report = RunStabilityBench(model, program, options, Progress);
  WriteFileAtomically(dir + "stability.csv", StabilityCsv(report));
  WriteFileAtomically(dir + "energy_drift.csv", EnergyDriftCsv(report));
  std::printf("%s", StabilitySummary(report).c_str());
  std::printf("\nwrote %sstability.csv and %senergy_drift.csv\n", dir.c_str(), dir.c_str());
}

}  // namespace

void RegisterBench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Benchmarks: run time against error, and numerical stability stress tests");
  bench->require_subcommand(1);

  auto acc = std::make_shared<AccuracyFlags>();
  CLI::App* a = bench->add_subcommand(
      "accuracy",
      "Every integrator on a ladder of steps (0.01 down to 0.0025/16) for the unoptimised and an "
      "evolved program: position error against an adaptive Dormand-Prince reference at t = 10 "
      "and at the end of the first gait cycle, relative error of the 1000-time-unit fitness, "
      "and wall time per 1000 time units. Prints a table; writes OUT/accuracy.csv");
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

  auto stab = std::make_shared<StabilityFlags>();
  CLI::App* s = bench->add_subcommand(
      "stability",
      "Stress tests: (a) spring stiffness x1..x100 against step size, stable or diverged, per "
      "integrator (OUT/stability.csv); (b) energy drift over 1000 time units in free flight, "
      "gravity on, ground and damping off (OUT/energy_drift.csv); (c) all -8, all +7 and random "
      "genomes with euler at dt 0.0025: walked, fell or diverged, never a silent NaN");
  AddCommonOptions(s, stab->common);
  s->add_option("--genomes", stab->genomes, "Random genomes to run")->capture_default_str();
  s->add_option("--seed", stab->seed, "Seed of the random genomes")->capture_default_str();
  s->add_option("--threads", stab->threads, "Threads for the genome runs (0: all cores)")
      ->capture_default_str();
  s->callback([stab] { RunStability(*stab); });

  // `hexgait bench speed` is added here by AddBenchSpeed(*bench) (the batched speed path).
}

}  // namespace hexgait
