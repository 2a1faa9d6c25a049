// The integrator benchmarks (accuracy, stability), the speed of the step paths and the early
// stop, as requests (run/bench_request.h).
#include <algorithm>
#include <sstream>

#include "ga/evolution.h"
#include "ga/genome_io.h"
#include "run/bench_request.h"
#include "run/io_paths.h"
#include "search/ga_optimizer.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {
namespace {

void RequireThreads(int threads) {
  if (threads < 0 || threads > 1024) throw InputError("--threads must be in [0, 1024]");
}

}  // namespace

std::vector<IntegratorKind> ParseIntegratorList(const std::string& text) {
  if (text.empty()) return AllIntegrators();
  std::vector<IntegratorKind> kinds;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) kinds.push_back(ParseIntegrator(name));
  if (kinds.empty()) throw InputError("--integrators: no integrator named");
  return kinds;
}

AccuracyResult MeasureAccuracyToFolder(const AccuracyRequest& request, const LogLine& note) {
  const BenchFolderRequest& common = request.common;
  IoPaths()
      .Input("--genome", request.genome_path)
      .Output("--out", common.out_dir + "/accuracy.csv")
      .Check();
  AccuracyOptions options;
  options.integrators = ParseIntegratorList(common.integrators);
  if (!(request.reference_tolerance > 0 && request.reference_tolerance < 1e-3))
    throw InputError("--reference-tolerance must be in (0, 1e-3)");
  options.reference_tolerance = request.reference_tolerance;
  options.steps = DefaultStepLadder();
  if (request.full) options.implicit_min_dt = 0;
  SceneOptions scene_options;
  scene_options.creature_path = common.creature;
  const Scene scene = LoadScene(scene_options);
  const CreatureModel& model = scene.model;
  const MotorProgram& program = scene.program;
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<AccuracyProgram> programs = {{"unoptimized", Genome(layout)}};
  if (common.quick) {
    // One program, three steps, just past the first gait cycle.
    options.steps = {0.01, 0.005, 0.0025};
    options.duration = program.cycle_period + 4;
    options.reference_tolerance = std::max(options.reference_tolerance, 1e-8);
  }
  if (!request.genome_path.empty()) {
    programs.push_back({"evolved", LoadGenomeFile(request.genome_path, layout)});
  } else if (!common.quick) {
    note("evolving the 'evolved' program: hexgait evolve --seed 1 (the paper's settings)");
    EvolutionParams params;
    params.seed = 1;
    programs.push_back({"evolved", Evolve(model, program, params, {}).best->genome});
  }
  OutputFolder out(common.out_dir, "accuracy.csv");
  AccuracyResult result;
  result.report = RunAccuracyBench(model, program, programs, options, note);
  result.csv_path = out.path() + "accuracy.csv";
  WriteFileAtomically(result.csv_path, AccuracyCsv(result.report));
  out.Keep();
  return result;
}

StabilityResult MeasureStabilityToFolder(const StabilityRequest& request, const LogLine& note) {
  const BenchFolderRequest& common = request.common;
  StabilityOptions options;
  options.integrators = ParseIntegratorList(common.integrators);
  if (request.genomes < 0 || request.genomes > 1000000)
    throw InputError("--genomes must be in [0, 1000000]");
  RequireThreads(request.threads);
  options.random_genomes = request.genomes;
  options.seed = request.seed;
  options.threads = request.threads;
  if (common.quick) {
    options.stiffness_multipliers = {1, 10, 100};
    options.steps = {0.02, 0.005, 0.00125};
    options.map_duration = 5;
    options.drift_duration = 50;
    options.random_genomes = std::min(options.random_genomes, 4);
  }
  SceneOptions scene_options;
  scene_options.creature_path = common.creature;
  const Scene scene = LoadScene(scene_options);
  const CreatureModel& model = scene.model;
  const MotorProgram& program = scene.program;
  OutputFolder out(common.out_dir, "stability.csv");
  StabilityResult result;
  result.report = RunStabilityBench(model, program, options, note);
  result.stability_csv = out.path() + "stability.csv";
  result.drift_csv = out.path() + "energy_drift.csv";
  WriteFileAtomically(result.stability_csv, StabilityCsv(result.report));
  WriteFileAtomically(result.drift_csv, EnergyDriftCsv(result.report));
  out.Keep();
  return result;
}

SpeedReport MeasureSpeedOfPaths(const SpeedRequest& request) {
  const SpeedSettings& s = request.settings;
  if (!(s.seconds > 0 && s.seconds <= 60)) throw InputError("--seconds must be in (0, 60]");
  if (s.repeats < 1 || s.repeats > 100) throw InputError("--repeats must be in [1, 100]");
  RequireThreads(s.threads);
  if (s.repertoire_children < 0 || s.repertoire_children > 100000) {
    throw InputError("--repertoire-children must be in [0, 100000]");
  }
  const Scene scene = LoadScene(SceneOptions{});
  SpeedSettings settings = s;
  if (request.time_paper_experiment) {
    settings.paper_experiment = [&scene](const EvolutionParams& params) {
      return Evolve(scene.model, scene.program, params, {});
    };
  }
  return MeasureSpeed(scene.model, scene.program, settings);
}

EarlyStopReport MeasureEarlyStopOf(const EarlyStopSettings& settings) {
  if (settings.genomes < 1 || settings.genomes > 100000) {
    throw InputError("--genomes must be in [1, 100000]");
  }
  RequireThreads(settings.threads);
  const Scene scene = LoadScene(SceneOptions{});
  return MeasureEarlyStop(scene.model, scene.program, settings);
}

}  // namespace hexgait
