// hexgait endurance: how long evolved open-loop gaits last, and how fragile they are, into a
// folder of CSVs, a survival figure and Markdown tables (run/endurance_run.h).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "run/endurance_run.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

struct EnduranceOptions {
  EnduranceRunSettings study;
  bool quiet = false;
};

void Run(const EnduranceOptions& opt) {
  EnduranceObserver observer;
  ProgressBar bar("endurance");
  if (!opt.quiet) {
    observer.drawing = [](int wanted, double test_time) {
      std::printf("endurance: drawing random genomes until %d do not fall in %g time units\n",
                  wanted, test_time);
      std::fflush(stdout);
    };
    observer.drew = [](size_t found, int tried) {
      std::printf("  %zu of %d random genomes did not fall\n", found, tried);
    };
    observer.started = [&opt](size_t gaits, const std::vector<EnduranceCondition>& conditions,
                              int threads) {
      std::printf("endurance: %zu gaits, %zu conditions, %d threads -> %s\n", gaits,
                  conditions.size(), threads, opt.study.out_dir.c_str());
      for (const EnduranceCondition& c : conditions) {
        std::printf("  %-18s %s, to t = %g%s\n", c.name.c_str(), c.label.c_str(), c.horizon,
                    c.trials > 1 ? (", " + std::to_string(c.trials) + " trials").c_str() : "");
      }
      std::fflush(stdout);
    };
    observer.progress = bar.Hook();
  }
  const EnduranceOutcome outcome = RunEnduranceStudy(opt.study, observer);
  bar.Clear();
  std::printf("%s\nwrote %s/ (endurance.csv, survival.png, table.md) in %.0f s\n",
              outcome.tables.c_str(), opt.study.out_dir.c_str(), outcome.seconds);
}

}  // namespace

void RegisterEndurance(CLI::App& app) {
  auto opt = std::make_shared<EnduranceOptions>();
  EnduranceRunSettings& r = opt->study;
  EnduranceSettings& s = r.settings;
  CLI::App* cmd = app.add_subcommand(
      "endurance",
      "How long evolved gaits last past the test, and under a push, a slope, a creature built "
      "a few percent off, another integrator or step: survival figure, CSV, tables");
  cmd->add_option("--genome", r.genomes, "Genome files to run (group 'genome files')");
  cmd->add_option("--run", r.runs,
                  "'hexgait evolve' folders: their best.genome (default: out/run, when no "
                  "--genome, --run or --runs is given)");
  cmd->add_option("--runs", r.sweeps,
                  "'hexgait sweep' folders: every seed's best.genome, grouped by budget");
  cmd->add_option("--random", r.random,
                  "Also run this many random genomes that happened not to fall in the test "
                  "(0: none)")
      ->check(CLI::Range(0, 10000))
      ->capture_default_str();
  cmd->add_option("--random-tries", r.random_tries,
                  "Draw at most this many random genomes looking for them")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  cmd->add_option("--time", r.time, "The test: simulated time the gaits were evolved for")
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
  cmd->add_option("--other-integrator", r.other_integrator,
                  "Also run every gait with this integrator (the test's: skip)")
      ->capture_default_str();
  cmd->add_option("--step-factor", s.step_factor,
                  "Also run every gait at this fraction of the test's step (1: skip)")
      ->capture_default_str();
  AddSeedOption(cmd, s.seed, "Seed for push phases, jitter and random genomes");
  cmd->add_option("--threads", s.threads, "Threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--out", r.out_dir, "Folder to write (replaced whole)")->capture_default_str();
  cmd->add_flag("--quiet", opt->quiet, "No progress, only the tables and where they went");
  AddSceneOptions(cmd, r.scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
