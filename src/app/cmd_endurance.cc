// hexgait endurance: how long evolved open-loop gaits last, and how fragile they are
// (study/endurance.h), into a folder of CSVs, a survival figure and Markdown tables
// (report/endurance_report.h).
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "util/progress_bar.h"
#include "run/run_state.h"
#include "run/sweep_summary.h"
#include "eval/evaluator.h"
#include "ga/genome_io.h"
#include "report/endurance_report.h"
#include "record/endurance_record.h"
#include "run/run_state.h"
#include "study/endurance.h"
#include "util/atomic_dir.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct EnduranceOptions {
  SceneOptions scene;
  std::vector<std::string> genomes, runs, sweeps;
  int random = 20;
  int random_tries = 5000;
  double time = kPaperDuration;
  std::string other_integrator = "symplectic-euler";
  EnduranceSettings settings;
  std::string out_dir = "out/endurance";
  bool quiet = false;
};

constexpr const char* kEnduranceMarker = ".hexgait-endurance";

std::string BudgetLabel(const std::string& run_folder) {
  const SeedSummary s = ReadSeedSummary(run_folder);
  return "population " + std::to_string(s.population) + ", " + std::to_string(s.generations) +
         " generations";
}

// The gaits the options name, each decoded once; --run and --runs folders are grouped by their
// budget (population and generations), so two sweeps of one budget make one group.
std::vector<EnduranceGait> LoadGaits(const EnduranceOptions& opt, const Scene& scene,
                                     std::vector<std::string>* run_folders) {
  std::vector<EnduranceGait> gaits;
  const auto add = [&](const std::string& group, const std::string& genome_path) {
    GenomeChoice choice;
    choice.path = genome_path;
    const Genome genome = LoadGenomeChoice(choice, scene, nullptr);
    gaits.push_back({group, genome_path, PerturbedRestLengths(scene.model, scene.program, genome)});
  };
  for (const std::string& path : opt.genomes) add("genome files", path);
  for (const std::string& run : opt.runs) add(BudgetLabel(run), run + "/best.genome");
  for (const std::string& sweep : opt.sweeps) {
    const std::vector<std::string> folders = RunFoldersOf(sweep);
    if (folders.empty()) throw InputError("--runs '" + sweep + "': holds no seed folders");
    const std::string group = BudgetLabel(folders.front());
    for (const std::string& run : folders) {
      RefuseUnfinishedRun(run, "--runs");
      add(group, run + "/best.genome");
      run_folders->push_back(run);
    }
  }
  return gaits;
}

void Run(EnduranceOptions opt) {
  const auto start = std::chrono::steady_clock::now();
  if (opt.genomes.empty() && opt.runs.empty() && opt.sweeps.empty()) opt.runs = {"out/run"};
  IoPaths paths = SceneInputs(opt.scene);
  for (const std::string& p : opt.genomes) paths.Input("--genome", p);
  for (const std::string& p : opt.runs) paths.Input("--run", p);
  for (const std::string& p : opt.sweeps) paths.Input("--runs", p);
  paths.OutputFolder("--out", opt.out_dir).Check();
  for (const std::string& p : opt.runs) RefuseUnfinishedRun(p, "--run");

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
  for (const EnduranceCondition& c : conditions) factor += c.horizon / opt.time * c.trials;
  const int expected_gaits = static_cast<int>(gaits.size()) + opt.random;
  MakeRunOptions(opt.scene, opt.time,
                 static_cast<int>(std::min(2e9, factor * std::max(1, expected_gaits))));
  AtomicDir dir(opt.out_dir, kEnduranceMarker, "--out");

  int tried = 0;
  if (opt.random > 0) {
    if (!opt.quiet) {
      std::printf("endurance: drawing random genomes until %d do not fall in %g time units\n",
                  opt.random, opt.time);
      std::fflush(stdout);
    }
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
    if (!opt.quiet) {
      std::printf("  %zu of %d random genomes did not fall\n", found.size(), tried);
    }
  }
  if (gaits.empty())
    throw InputError(
        "no gaits to run: no --genome, --run or --runs, and no random genome stood the test");
  if (!opt.quiet) {
    std::printf("endurance: %zu gaits, %zu conditions, %d threads -> %s\n", gaits.size(),
                conditions.size(), ResolveThreadCount(s.threads), opt.out_dir.c_str());
    for (const EnduranceCondition& c : conditions) {
      std::printf("  %-18s %s, to t = %g%s\n", c.name.c_str(), c.label.c_str(), c.horizon,
                  c.trials > 1 ? (", " + std::to_string(c.trials) + " trials").c_str() : "");
    }
    std::fflush(stdout);
  }
  ProgressBar bar("endurance");
  const EnduranceResult result =
      RunEndurance(scene.model, scene.program, gaits, s, [&](double fraction) {
        if (!opt.quiet) bar.Update(fraction);
      });
  bar.Clear();
  const std::string tables = WriteEnduranceReport(dir.temp_path(), gaits, s, result);

  EnduranceRecord record;
  record.test_time = opt.time;
  record.dt = s.test.dt;
  record.integrator = IntegratorName(s.test.integrator);
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
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteFileAtomically(dir.File("endurance.json"), EnduranceRecordJson(record).dump(2) + "\n");
  dir.Commit();
  std::printf("%s\nwrote %s/ (endurance.csv, survival.png, table.md) in %.0f s\n", tables.c_str(),
              opt.out_dir.c_str(), record.wall_seconds);
}

}  // namespace

void RegisterEndurance(CLI::App& app) {
  auto opt = std::make_shared<EnduranceOptions>();
  EnduranceSettings& s = opt->settings;
  CLI::App* cmd = app.add_subcommand(
      "endurance",
      "How long evolved gaits last past the test, and under a push, a slope, a creature built "
      "a few percent off, another integrator or step: survival figure, CSV, tables");
  cmd->add_option("--genome", opt->genomes, "Genome files to run (group 'genome files')");
  cmd->add_option("--run", opt->runs,
                  "'hexgait evolve' folders: their best.genome (default: out/run, when no "
                  "--genome, --run or --runs is given)");
  cmd->add_option("--runs", opt->sweeps,
                  "'hexgait sweep' folders: every seed's best.genome, grouped by budget");
  cmd->add_option("--random", opt->random,
                  "Also run this many random genomes that happened not to fall in the test "
                  "(0: none)")
      ->check(CLI::Range(0, 10000))
      ->capture_default_str();
  cmd->add_option("--random-tries", opt->random_tries,
                  "Draw at most this many random genomes looking for them")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  cmd->add_option("--time", opt->time, "The test: simulated time the gaits were evolved for")
      ->capture_default_str();
  cmd->add_option("--long", s.long_factor,
                  "The unperturbed run lasts this many times the test (stops at the fall)")
      ->capture_default_str();
  cmd->add_option("--horizon", s.perturbed_factor,
                  "Every perturbed run lasts this many times the test (stops at the fall)")
      ->capture_default_str();
  cmd->add_option("--push", s.push_impulse,
                  "Sideways push just after the test, at a random phase: impulse (mass x "
                  "length / time) shared by the body particles (0: no push)")
      ->capture_default_str();
  cmd->add_option("--slope", s.slope_degrees,
                  "Slope in degrees, run uphill and downhill (gravity tilted; 0: none)")
      ->capture_default_str();
  cmd->add_option("--jitter", s.jitter,
                  "Every spring stiffness and particle mass times a random factor within "
                  "1 +- this (0: none)")
      ->capture_default_str();
  cmd->add_option("--trials", s.trials, "Push phases, and jittered creatures, per gait")
      ->capture_default_str();
  cmd->add_option("--other-integrator", opt->other_integrator,
                  "Also run every gait with this integrator (the test's: skip)")
      ->capture_default_str();
  cmd->add_option("--step-factor", s.step_factor,
                  "Also run every gait at this fraction of the test's step (1: skip)")
      ->capture_default_str();
  AddSeedOption(cmd, s.seed, "Seed for push phases, jitter and random genomes");
  cmd->add_option("--threads", s.threads, "Threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--out", opt->out_dir, "Folder to write (replaced whole)")->capture_default_str();
  cmd->add_flag("--quiet", opt->quiet, "No progress, only the tables and where they went");
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
