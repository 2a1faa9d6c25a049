// The flags of one evolve run, shared by `hexgait evolve` (one seed) and `hexgait sweep` (a run
// per seed): the same flags into the same settings (run/evolve_run.h).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "app/param_flags.h"
#include "run/evolve_run.h"

namespace hexgait {

struct EvolveOptions {
  EvolveSettings settings;
  const CLI::Option* population_option = nullptr;  // whether --population was given
  std::unique_ptr<ParamFlags> algorithm_flags;     // every optimizer's own parameters
  bool quiet = false;
};

// The flags a resumed run takes from its checkpoint instead: those of AddEvolveRunOptions that
// change results, with every optimizer's own parameters.
std::vector<std::string> EvolveRunFlags(const EvolveOptions& options);

// The flags that set a run's parameters (algorithm, population, generations, rates, time,
// precision, threads, creature, ...), all but --seed, --out, --resume and --quiet.
void AddEvolveRunOptions(CLI::App* cmd, EvolveOptions& opt);

// The settings the parsed flags describe (with whether --population was given).
EvolveSettings SettingsOf(const EvolveOptions& options);

}  // namespace hexgait
