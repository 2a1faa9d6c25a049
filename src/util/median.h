// The one median of the project (benchmarks, sweep and endurance tables, figures).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace hexgait {

// The median of `values`, averaging the middle two for an even count; `if_empty` when there are
// none (NaN unless the caller's table prints something else there).
inline double Median(std::vector<double> values, double if_empty = NAN) {
  if (values.empty()) return if_empty;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace hexgait
