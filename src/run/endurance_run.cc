#include "run/endurance_run.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "motor/leg_targets.h"
#include "record/endurance_record.h"
#include "record/run_record.h"
#include "report/endurance_report.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/run_state.h"
#include "run/runtime_needs.h"
#include "run/sweep_summary.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {
namespace {

constexpr const char* kEnduranceMarker = ".hexgait-endurance";

std::string BudgetLabel(const std::string& run_folder) {
  const SeedSummary s = ReadSeedSummary(run_folder);
  return "population " + std::to_string(s.population) + ", " + std::to_string(s.generations) +
         " generations";
}

// The gaits the options name, each decoded once; --run and --runs folders are grouped by their
// budget (population and generations), so two sweeps of one budget make one group.
std::vector<EnduranceGait> LoadGaits(const EnduranceRunSettings& opt, const Scene& scene,
                                     std::vector<std::string>* run_folders) {
  std::vector<EnduranceGait> gaits;
  const auto add = [&](const std::string& group, const std::string& genome_path) {
    GenomeChoice choice;
    choice.path = genome_path;
    const Genome genome = LoadGenomeChoice(choice, scene, nullptr);
    gaits.push_back({group, genome_path, PerturbedRestLengths(scene.model, scene.program, genome)});
  };
  // A folder's problem is reported with the option and the folder the user gave.
  const auto naming = [](const std::string& flag, const std::string& given, const auto& load) {
    try {
      load();
    } catch (const InputError& e) {
      throw InputError(flag + " '" + given + "': " + e.what());
    }
  };
  for (const std::string& path : opt.genomes) add("genome files", path);
  for (const std::string& run : opt.runs) {
    naming("--run", run, [&] { add(BudgetLabel(run), run + "/best.genome"); });
  }
  for (const std::string& sweep : opt.sweeps) {
    const std::vector<std::string> folders = RunFoldersOf(sweep);
    if (folders.empty()) throw InputError("--runs '" + sweep + "': holds no seed folders");
    std::string group;
    naming("--runs", sweep, [&] { group = BudgetLabel(folders.front()); });
    for (const std::string& run : folders) {
      RefuseUnfinishedRun(run, "--runs", "evolve");
      naming("--runs", run, [&] { add(group, run + "/best.genome"); });
      run_folders->push_back(run);
    }
  }
  return gaits;
}

}  // namespace

EnduranceOutcome RunEnduranceStudy(EnduranceRunSettings opt, const EnduranceObserver& observer) {
  const auto start = Clock::now();
  if (opt.genomes.empty() && opt.runs.empty() && opt.sweeps.empty()) opt.runs = {"out/run"};
  IoPaths paths;
  for (const std::string& p : opt.genomes) paths.Input("--genome", p);
  for (const std::string& p : opt.runs) paths.Input("--run", p);
  for (const std::string& p : opt.sweeps) paths.Input("--runs", p);
  paths.OutputFolder("--out", opt.out_dir).Check();
  for (const std::string& p : opt.runs) RefuseUnfinishedRun(p, "--run", "evolve");
  // Every folder's gait is tested on the scene it was evolved on: one scene for all of them.
  std::vector<FolderArg> folders;
  for (const std::string& p : opt.runs) folders.push_back({"--run", p});
  for (const std::string& sweep : opt.sweeps) {
    for (const std::string& run : RunFoldersOf(sweep)) {
      RefuseUnfinishedRun(run, "--runs", "evolve");
      folders.push_back({"--runs", run});
    }
  }
  opt.scene = SceneOfFolders(opt.scene, folders);
  SceneInputs(opt.scene).Check();

  EnduranceSettings& s = opt.settings;
  s.test = MakeRunOptions(opt.scene, opt.time);
  s.other_integrator = ParseIntegrator(opt.other_integrator);
  CheckEnduranceSettings(s);
  const Scene scene = LoadScene(opt.scene);
  std::vector<std::string> run_folders;
  std::vector<EnduranceGait> gaits = LoadGaits(opt, scene, &run_folders);
  const std::vector<EnduranceCondition> conditions = EnduranceConditions(s, s.test.integrator);
  // The whole study in test-length runs, for the over-an-hour check (--allow-long).
  double factor = 1;
  for (const EnduranceCondition& c : conditions) {
    factor += c.horizon / opt.time / c.step_fraction * c.trials;
  }
  const int expected_gaits = static_cast<int>(gaits.size()) + opt.random;
  MakeRunOptions(opt.scene, opt.time,
                 static_cast<int>(std::min(2e9, factor * std::max(1, expected_gaits))));
  RuntimeNeeds figures;
  figures.figures = true;  // drawn after every trial
  CheckRuntime(figures);
  AtomicDir dir(opt.out_dir, kEnduranceMarker, "--out");

  int tried = 0;
  if (opt.random > 0) {
    if (observer.drawing) observer.drawing(opt.random, opt.time);
    const auto layout = MakeGenomeLayout(scene.model, scene.program, false);
    const std::vector<Genome> found =
        StandingRandomGenomes(scene.model, scene.program, layout, opt.random, opt.random_tries,
                              s.test, s.seed, s.threads, &tried);
    const std::string group = "random genomes that stood the test";
    for (size_t i = 0; i < found.size(); ++i) {
      gaits.push_back({group, "random " + std::to_string(i + 1),
                       PerturbedRestLengths(scene.model, scene.program, found[i])});
      WriteFileAtomically(dir.File("random-" + std::to_string(i + 1) + ".genome"),
                          FormatGenome(found[i], "random genome " + std::to_string(i + 1) +
                                                     " of 'hexgait endurance --seed " +
                                                     std::to_string(s.seed) + "'"));
    }
    if (observer.drew) observer.drew(found.size(), tried);
  }
  if (gaits.empty())
    throw InputError(
        "no gaits to run: no --genome, --run or --runs, and no random genome stood the test");
  if (observer.started) observer.started(gaits.size(), conditions, ResolveThreadCount(s.threads));
  const EnduranceResult result =
      RunEndurance(scene.model, scene.program, gaits, s, observer.progress);
  const std::string tables = WriteEnduranceReport(dir.temp_path(), gaits, s, result);

  EnduranceRecord record;
  record.test_time = opt.time;
  record.dt = s.test.dt;
  record.integrator = IntegratorName(s.test.integrator);
  record.damage = scene.model.damage;
  record.long_factor = s.long_factor;
  record.perturbed_factor = s.perturbed_factor;
  record.push_impulse = s.push_impulse;
  record.slope_degrees = s.slope_degrees;
  record.jitter = s.jitter;
  record.trials = s.trials;
  record.step_factor = s.step_factor;
  record.seed = s.seed;
  record.random_wanted = opt.random;
  record.random_tried = tried;
  for (const EnduranceCondition& c : result.conditions) {
    record.conditions.push_back({c.name, c.label, c.horizon, c.trials});
  }
  for (size_t g = 0; g < gaits.size(); ++g) {
    record.gaits.push_back({gaits[g].group, gaits[g].name, OutcomeOf(result.test[g])});
  }
  record.wall_seconds = SecondsSince(start);
  WriteFileAtomically(dir.File("endurance.json"), EnduranceRecordJson(record).dump(2) + "\n");
  dir.Commit();
  return {tables, record.wall_seconds};
}

}  // namespace hexgait
