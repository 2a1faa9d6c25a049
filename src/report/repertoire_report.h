// The files of `hexgait repertoire`: the archive as CSV, coverage and QD-score against
// evaluations (CSV and figure), the map (the N-dimensional grid drawn as nested 2-D blocks,
// as Cully et al. draw theirs) and a Markdown table comparing MAP-Elites with the paper's GA
// on the same budget.
#pragma once

#include <string>
#include <vector>

#include "ga/map_elites.h"
#include "model/creature.h"

namespace hexgait {

// One method's run, for the comparison: its archive of standing gaits and how it grew.
struct RepertoireMethod {
  std::string name;  // "MAP-Elites", "paper's GA (population 100)"
  const Archive* archive = nullptr;
  std::vector<ArchiveStats> history;
  long long evaluations = 0;
  long long diverged = 0;  // of those evaluations, simulations that diverged
  double seconds = 0;
  // The best fitness of any evaluation, fallen or not (the GA's own fitness: a gait may win
  // by sliding far and falling).
  double best_fitness = 0;
};

// Writes archive.csv, progress.csv/.gp/.png/.svg, map.csv/.gp/.png/.svg and table.md into
// `dir`, the first method being MAP-Elites (whose archive is listed and mapped, with the
// `showcase` cells numbered on the map). Returns the tables.
std::string WriteRepertoireReport(const std::string& dir, const CreatureModel& model,
                                  double gene_length_step, const BehaviourDescriptor& descriptor,
                                  const std::vector<RepertoireMethod>& methods,
                                  const std::vector<int>& showcase);

// "0.62 0.50 0.71 / 0.55 0.80 0.49": an elite's behaviour, as captions and tables show it;
// with six legs, right then left, three per line ("lines" gets the halves).
std::vector<std::string> BehaviourLines(const CreatureModel& model,
                                        const BehaviourDescriptor& descriptor,
                                        const RunResult& result);

}  // namespace hexgait
