// One evolve run into a folder, shared by `hexgait evolve` (one seed) and `hexgait sweep` (a
// run per seed): the same flags, the same files, the same bytes.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "ga/evolution.h"
#include "sim/run.h"

namespace hexgait {

struct EvolveOptions {
  SceneOptions scene;
  std::string algorithm = "ga";                    // an optimizer of search/optimizers.cc
  const CLI::Option* population_option = nullptr;  // whether --population was given
  bool early_stop = false;
  std::string precision = "double";
  EvolutionParams params;
  double time = kPaperDuration;
  std::string out_dir = "out/run";
  std::string resume_dir;                    // continue the run whose checkpoint is here
  std::vector<std::string> run_flags_given;  // GA flags on the command line (not with --resume)
  bool quiet = false;
  // This process's threads only, never MPI ranks: sweep hands whole runs to ranks instead.
  bool local_only = false;
};

// The flags that set a run's parameters (population, generations, rates, time, precision,
// threads, creature, ...), all but --seed, --out, --resume and --quiet.
void AddEvolveRunOptions(CLI::App* cmd, EvolveOptions& opt);

// Runs the search (the GA or CMA-ES) into opt.out_dir (or continues opt.resume_dir) and writes
// checkpoint.json, fitness.csv, best.genome and run.json. Throws InputError on bad input, Stopped
// after a generation's checkpoint once a stop was requested.
void RunEvolve(const EvolveOptions& opt);

}  // namespace hexgait
