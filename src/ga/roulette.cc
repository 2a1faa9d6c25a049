#include "ga/roulette.h"

#include <algorithm>

namespace hexgait {

int RouletteSelect(const std::vector<double>& weights, double u) {
  const int n = static_cast<int>(weights.size());
  double total = 0;
  for (double w : weights) total += std::max(w, 0.0);
  if (!(total > 0)) return std::min(static_cast<int>(u * n), n - 1);
  double target = u * total;
  for (int i = 0; i < n; ++i) {
    const double w = std::max(weights[i], 0.0);
    if (target < w) return i;
    target -= w;
  }
  // Rounding left `target` just past the last slice: take the last positive weight.
  for (int i = n - 1; i >= 0; --i) {
    if (weights[i] > 0) return i;
  }
  return n - 1;
}

}  // namespace hexgait
