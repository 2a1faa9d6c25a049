// Roulette-wheel (fitness-proportional) selection.
#pragma once

#include <vector>

namespace hexgait {

// Index i with probability weight[i] / sum(weight). Negative weights count as zero (a creature
// that walked backwards gets no offspring by fitness); if every weight is zero, the choice is
// uniform. `u` is a uniform number in [0, 1).
int RouletteSelect(const std::vector<double>& weights, double u);

}  // namespace hexgait
