// The summary of a sweep: one row per seed from each DIR/seed-K/run.json, as summary.csv, and
// the Markdown row of docs/results.md's seeds table.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hexgait {

struct SeedSummary {
  uint64_t seed = 0;
  int population = 0, generations = 0, evaluations = 0;
  double unoptimized_distance = 0;
  bool unoptimized_fell = false;
  int unoptimized_fall_cycle = -1;  // -1: did not fall
  double best_distance = 0;
  bool best_fell = false;
  int best_fall_cycle = -1;
  double ratio = 0;  // best / unoptimized; 0 when the unoptimized program went backwards
  // Diverged simulations are their own outcome, never folded into "fell" or "did not fall".
  bool unoptimized_diverged = false, best_diverged = false;
  int diverged_evaluations = 0;  // of the run's evaluations
};

// The run folders of `folder`: its seed-K/ folders in seed order when it is a sweep's (it has
// a .hexgait-sweep marker), else the folder itself. For `figures --runs`.
std::vector<std::string> RunFoldersOf(const std::string& folder);

// Reads FOLDER/run.json as evolve writes it; throws InputError naming what is missing.
SeedSummary ReadSeedSummary(const std::string& folder);

std::string SummaryCsv(const std::vector<SeedSummary>& seeds);

// The table's header and one row: budget, seeds, evaluations per run, unoptimized distance
// (fall cycle), best/unoptimized median, worst and best, and how many seeds' best does not
// fall. `seeds_text` is the --seeds value as given ("1-20").
std::string SeedTableMarkdown(const std::vector<SeedSummary>& seeds, const std::string& seeds_text);

}  // namespace hexgait
