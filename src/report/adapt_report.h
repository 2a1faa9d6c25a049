// The figure of `hexgait adapt`: each trial's distance and the best so far against the trial
// number, with the intact best gait on the damaged creature and the best elite there (found by
// running them all) as lines: how far adaptation got, and in how few trials.
#pragma once

#include <string>
#include <vector>

namespace hexgait {

struct AdaptFigureData {
  std::string damage;
  std::vector<double> trial_distance, best_so_far;  // per trial
  double intact_best_on_damaged = 0;
  double best_elite_on_damaged = 0;
};

// Writes adapt.csv, adapt.gp, adapt.png and adapt.svg into `dir` (gnuplot; InputError when it
// is missing).
void WriteAdaptFigure(const std::string& dir, const AdaptFigureData& data);

}  // namespace hexgait
