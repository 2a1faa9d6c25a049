// A sweep: whole independent evolve runs, one per seed, into DIR/seed-K/, then DIR/summary.csv
// and DIR/table.md (the seeds table of docs/results.md); what `hexgait sweep` runs. The runs
// share this machine's threads, or, under mpirun, go to ranks as they become free (rank 0 hands
// them out and writes the summary; each rank writes its seeds' folders, so DIR must be on a file
// system every rank sees). Every seed's folder holds the same bytes `hexgait evolve --seed K`
// writes, and a later sweep into the same folder keeps the seeds already done.
#pragma once

#include <functional>
#include <string>

#include "run/evolve_run.h"
#include "run/sweep_summary.h"

namespace hexgait {

struct SweepSettings {
  EvolveSettings run;  // every run's settings; the seed and folder are set per run
  std::string seeds = "1-20";
  std::string out_dir = "out/sweep";
};

// What a sweep reports as it goes; every member may be left empty.
struct SweepObserver {
  // Before the first run: seeds in all, those already done, and the workers (threads, or MPI
  // ranks when `ranks`).
  std::function<void(size_t seeds, size_t already_done, int workers, bool ranks)> started;
  // A seed's run is complete: its summary, and how many of all are done.
  std::function<void(const SeedSummary& seed, size_t done, size_t total)> seed_done;
};

struct SweepOutcome {
  std::string table;  // table.md's text
};

// Throws InputError on bad input (before any run), Stopped on Ctrl-C with how many seeds are
// done (the next sweep into the folder continues).
SweepOutcome RunSweep(const SweepSettings& settings, const SweepObserver& observer = {});

// "1-20", "3,5,9", "1-4,10": in the order given, each seed once; throws InputError naming
// --seeds.
std::vector<unsigned long long> ParseSeeds(const std::string& text);

}  // namespace hexgait
