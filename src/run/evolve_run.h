// One evolve run into a folder: what `hexgait evolve` runs for one seed, `hexgait sweep` once
// per seed, and the same flags give the same files and bytes. The search (the GA or CMA-ES, by
// the registry of search/optimizers.cc) runs under the search driver; this owns the folder, the
// checks before the work, the checkpoint after every generation and the records at the end.
// What a run reports as it goes reaches the caller through EvolveObserver, so printing stays
// the command's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ga/evolution.h"
#include "record/run_record.h"
#include "run/scene.h"
#include "search/generational.h"
#include "search/stored_results.h"
#include "sim/step_loop.h"

namespace hexgait {

struct EvolveSettings {
  SceneOptions scene;
  std::string algorithm = "ga";   // an optimizer of search/optimizers.cc
  bool population_given = false;  // CMA-ES takes its own population (lambda) unless given
  bool early_stop = false;
  std::string precision = "double";
  EvolutionParams params;      // its settings are set from settings_given
  ParamValues settings_given;  // the optimizer's own parameters given (flags, keywords)
  double time = kPaperDuration;
  std::string out_dir = "out/run";
  std::string resume_dir;                    // continue the run whose checkpoint is here
  std::vector<std::string> run_flags_given;  // run flags on the command line (not with --resume)
  // This process's threads only, never MPI ranks: sweep hands whole runs to ranks instead.
  bool local_only = false;
};

// What a run tells its caller as it goes; every member may be left empty.
struct EvolveObserver {
  // The search is made (or resumed) and the folder taken, before the first evaluation.
  std::function<void(const GenerationalOptimizer& search, int threads, bool resumed)> started;
  // During the run: its evaluations done of its budget.
  Progress progress;
  // After each generation is told; `elapsed` seconds since the start.
  std::function<void(const GenerationalOptimizer& search, double elapsed)> generation;
  // After each checkpoint is written.
  std::function<void()> saved;
  // A resumed run's stored results were replayed and match (search/stored_results.h).
  std::function<void(const ReplayCheck& check)> replayed;
};

struct EvolveOutcome {
  std::string dir;  // the folder written, with a trailing slash
  RunResult unoptimized, best;
  RunRecord record;  // as written to run.json
};

// Runs the search into settings.out_dir (or continues settings.resume_dir) and writes
// checkpoint.json, fitness.csv, best.genome and run.json. Throws InputError on bad input (before
// anything is written), Stopped after a generation's checkpoint once a stop was requested.
EvolveOutcome RunEvolve(const EvolveSettings& settings, const EvolveObserver& observer = {});

// The search's parameters the settings describe (checked: the step, the time, the precision).
EvolutionParams SearchParamsOf(const EvolveSettings& settings);
// The long-run estimate (run/work_size.h) of one whole run on one thread, in seconds.
double EstimatedEvolveSeconds(const EvolveSettings& settings, const Scene& scene);

// "did not fall", "fell in cycle 3 (t = 150)" or "diverged".
std::string FallText(const RunResult& result);

}  // namespace hexgait
