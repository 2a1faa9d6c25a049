// hexgait sweep: whole independent evolve runs, one per seed, into DIR/seed-K/, then
// DIR/summary.csv and DIR/table.md (run/sweep_run.h); on threads, or across MPI ranks.
#include <cstdio>
#include <memory>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evolve_options.h"
#include "run/sweep_run.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct SweepOptions {
  EvolveOptions run;  // every run flag; seed and folder are set per run
  std::string seeds = "1-20";
  std::string out_dir = "out/sweep";
  bool quiet = false;
};

void Run(const SweepOptions& opt) {
  StopIsPolled();  // each run stops after its next generation's checkpoint
  SweepSettings settings;
  settings.run = SettingsOf(opt.run);
  settings.seeds = opt.seeds;
  settings.out_dir = opt.out_dir;
  SweepObserver observer;
  if (!opt.quiet) {
    const EvolutionParams& p = settings.run.params;
    observer.started = [&p](size_t seeds, size_t already_done, int workers, bool ranks) {
      std::fprintf(stderr,
                   "sweep: %zu seeds (%zu already done), population %d, %d generations, %d %s\n",
                   seeds, already_done, p.population, p.generations, workers,
                   ranks ? "MPI ranks running seeds" : "threads");
    };
    observer.seed_done = [](const SeedSummary& s, size_t done, size_t total) {
      std::fprintf(stderr, "sweep: seed %llu done (%zu of %zu): best %.4f, %.2fx unoptimized%s\n",
                   static_cast<unsigned long long>(s.seed), done, total, s.best_distance, s.ratio,
                   s.best_fell ? ", falls" : "");
    };
  }
  const SweepOutcome outcome = RunSweep(settings, observer);
  std::printf("%s", outcome.table.c_str());
  if (!opt.quiet) {
    std::fprintf(stderr, "sweep: wrote %s/seed-*/, %s/summary.csv and %s/table.md\n",
                 opt.out_dir.c_str(), opt.out_dir.c_str(), opt.out_dir.c_str());
  }
}

}  // namespace

void RegisterSweep(CLI::App& app) {
  auto opt = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Evolve once per seed (DIR/seed-K/, as 'evolve --seed K' writes it), then DIR/summary.csv "
      "and the seeds table; on threads, or across MPI ranks under mpirun");
  cmd->add_option("--seeds", opt->seeds, "Seeds to run: 1-20, 1,4,9 or 1-4,10")
      ->capture_default_str();
  cmd->add_option("--out", opt->out_dir,
                  "Folder for seed-K/ runs, summary.csv and table.md; an earlier sweep's "
                  "folder is continued (its finished seeds are kept)")
      ->capture_default_str();
  cmd->add_flag("--quiet", opt->quiet, "Print only the table");
  AddEvolveRunOptions(cmd, opt->run);
  Distributed(cmd);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
