// hexgait evolve: a generational search (the paper's GA by default, or CMA-ES; the registry of
// search/optimizers.cc) run by the search driver, with its outputs written to --out DIR.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evolve_options.h"
#include "run/evolve_run.h"
#include "search/generational.h"
#include "simd/isa.h"
#include "util/progress_bar.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

// Flags that change a run's results: a resumed run takes them from its checkpoint instead
// (with the optimizers' own parameters, EvolveRunFlags).
const char* const kRunFlags[] = {"--seed", "--algorithm",  "--population", "--generations",
                                 "--time", "--symmetric",  "--dt",         "--integrator",
                                 "--out",  "--early-stop", "--precision"};

void PrintStart(const GenerationalOptimizer& search, const std::string& out_dir, int threads,
                bool resumed) {
  if (resumed) std::printf("resuming %s %s\n", out_dir.c_str(), search.Position().c_str());
  std::printf("evolving with %s, %s, %d thread%s\n", search.Describe().c_str(),
              PrecisionName(search.params().precision).c_str(), threads, threads == 1 ? "" : "s");
  std::printf("%4s %12s %12s %12s %9s %9s\n", "gen", "best", "mean", "worst", "seconds", "elapsed");
  std::fflush(stdout);
}

void PrintGeneration(const GenerationalOptimizer& search, double elapsed) {
  const GenerationStats& g = search.result().history.back();
  const std::vector<Individual>& pop = search.generation();
  std::printf("%4d %12.4f %12.4f %12.4f %9.2f %9.2f\n", g.generation, g.best, g.mean, g.worst,
              g.seconds, elapsed);
  std::fflush(stdout);
  // A diverged individual gets fitness 0 and the run goes on, but never silently. Elites
  // (the first of a bred generation) were reported when they were evaluated.
  for (size_t i = search.first_new(); i < pop.size(); ++i) {
    const RunResult& r = pop[i].result;
    if (!r.diverged) continue;
    std::fprintf(stderr,
                 "hexgait: warning: generation %d, individual %zu diverged at t = %g (step "
                 "%lld): %s; fitness set to 0\n",
                 g.generation, i, r.diverge_time, r.diverge_step, r.diverge_reason.c_str());
  }
}

void PrintOutcome(const EvolveOutcome& outcome) {
  const RunRecord& r = outcome.record;
  const std::string& dir = outcome.dir;
  std::printf("\nunoptimized  distance %9.4f  %s\n", outcome.unoptimized.distance,
              FallText(outcome.unoptimized).c_str());
  std::printf("evolved      distance %9.4f  %s\n", r.best_fitness, FallText(outcome.best).c_str());
  if (outcome.unoptimized.distance > 0) {
    std::printf("ratio        %.2fx   (paper: 1064 -> 4070, 3.83x)\n",
                r.best_fitness / outcome.unoptimized.distance);
  }
  std::printf("%d evaluations in %.2f s; wrote %sfitness.csv, %sbest.genome, %srun.json\n",
              r.evaluations, r.wall_seconds, dir.c_str(), dir.c_str(), dir.c_str());
  int diverged = 0;
  for (const GenerationStats& g : r.history) diverged += g.diverged;
  if (diverged > 0) {
    std::printf(
        "%d of the %d evaluations diverged (fitness 0; neither fell nor stood); a smaller "
        "--dt or another --integrator avoids it\n",
        diverged, r.evaluations);
  }
}

// evolve's run, printed as it goes unless --quiet.
void Run(const EvolveSettings& settings, bool quiet) {
  StopIsPolled();  // stops after the next generation's checkpoint, saying how to resume
  EvolveObserver observer;
  ProgressBar bar("evaluating");
  if (!quiet) {
    const std::string out_dir =
        settings.resume_dir.empty() ? settings.out_dir : settings.resume_dir;
    observer.replayed = [](const ReplayCheck& check) {
      std::printf("checked the checkpoint: %s\n", check.Text("results").c_str());
    };
    observer.started = [out_dir](const GenerationalOptimizer& search, int threads, bool resumed) {
      PrintStart(search, out_dir, threads, resumed);
    };
    observer.progress = bar.Hook();
    observer.generation = [&bar](const GenerationalOptimizer& search, double elapsed) {
      bar.Clear();
      PrintGeneration(search, elapsed);
    };
  }
  observer.saved = [&bar] {
    if (StopRequested()) bar.Clear();
  };
  const EvolveOutcome outcome = RunEvolve(settings, observer);
  bar.Clear();
  if (!quiet) PrintOutcome(outcome);
}

}  // namespace

EvolveSettings SettingsOf(const EvolveOptions& options) {
  EvolveSettings settings = options.settings;
  settings.population_given = options.population_option && options.population_option->count() > 0;
  settings.settings_given = options.algorithm_flags->Given();
  return settings;
}

std::vector<std::string> EvolveRunFlags(const EvolveOptions& options) {
  std::vector<std::string> flags(std::begin(kRunFlags), std::end(kRunFlags));
  for (const std::string& flag : options.algorithm_flags->flags()) flags.push_back(flag);
  return flags;
}

void AddEvolveRunOptions(CLI::App* cmd, EvolveOptions& opt) {
  EvolveSettings& s = opt.settings;
  EvolutionParams& p = s.params;
  std::vector<std::string> algorithms;
  std::string summaries;
  for (const OptimizerKind* kind : OptimizerKinds()) {
    algorithms.push_back(kind->name);
    summaries += std::string("; ") + kind->name + ": " + kind->summary;
  }
  cmd->add_option("--algorithm", s.algorithm, "The search" + summaries)
      ->check(CLI::IsMember(algorithms))
      ->capture_default_str();
  opt.population_option =
      cmd->add_option("--population", p.population,
                      "Individuals per generation (paper: 4; cmaes: lambda, default 4 + 3 ln n)")
          ->capture_default_str();
  cmd->add_option("--generations", p.generations,
                  "Generations after the initial population (paper: 10)")
      ->capture_default_str();
  cmd->add_option("--threads", p.threads, "Evaluation threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--batch-lanes", p.batch_lanes,
                  "Creatures simulated in lock-step per batch (0: automatic, 1: one at a time); "
                  "the results do not depend on it")
      ->capture_default_str();
  AddPrecisionOption(cmd, s.precision,
                     "Number type of the simulation: double (bit-identical to 'simulate') or "
                     "float (faster; needs --integrator euler; its error is in 'hexgait bench "
                     "accuracy')");
  cmd->add_option("--time", s.time, "Simulated time per evaluation (time units)")
      ->capture_default_str();
  cmd->add_flag("--symmetric", p.symmetric,
                "Tie mirror-image springs: 60 genes instead of the paper's 120");
  std::vector<ParamOwner> owners;
  for (const OptimizerKind* kind : OptimizerKinds()) owners.emplace_back(kind->name, kind->params);
  opt.algorithm_flags = std::make_unique<ParamFlags>(cmd, owners);
  cmd->add_flag("--early-stop", s.early_stop,
                "End an evaluation once the creature has fallen and lain still for a gait cycle");
  AddSceneOptions(cmd, s.scene);
}

void RegisterEvolve(CLI::App& app) {
  auto opt = std::make_shared<EvolveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "evolve",
      "Evolve the motor program's rest lengths with the paper's genetic algorithm (or CMA-ES)");
  EvolveSettings& s = opt->settings;
  AddSeedOption(cmd, s.params.seed, "Random seed");
  cmd->add_option("--out", s.out_dir, "Folder for fitness.csv, best.genome and run.json")
      ->capture_default_str();
  cmd->add_option("--resume", s.resume_dir,
                  "Continue the interrupted run in this folder from its checkpoint.json (same "
                  "--creature and --motor; its parameters come from the checkpoint)");
  cmd->add_flag("--quiet", opt->quiet, "Print nothing; only write the files");
  AddEvolveRunOptions(cmd, *opt);
  Distributed(cmd);
  cmd->callback([opt, cmd] {
    EvolveSettings settings = SettingsOf(*opt);
    for (const std::string& flag : EvolveRunFlags(*opt)) {
      if (cmd->count(flag) > 0) settings.run_flags_given.push_back(flag);
    }
    Run(settings, opt->quiet);
  });
}

}  // namespace hexgait
