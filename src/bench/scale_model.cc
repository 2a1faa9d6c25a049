#include "bench/scale_model.h"

#include <algorithm>

namespace hexgait {
namespace {

// The slowest rank's compute: the largest share, in rounds of full batches on every core.
double Compute(const ClusterModel& m, long long population, int ranks) {
  const long long share = (population + ranks - 1) / ranks;
  const long long slots = static_cast<long long>(m.cores_per_rank) * m.lanes;
  const long long rounds = (share + slots - 1) / slots;
  return static_cast<double>(rounds) * m.lanes * m.seconds_per_eval;
}

// Rank 0 sends one header and one table message to every other rank and receives one result
// message from each, one after another; every byte for another rank crosses rank 0's link.
double Communication(const ClusterModel& m, long long population, int ranks) {
  if (ranks <= 1) return 0;
  const double remote = static_cast<double>(population) * (ranks - 1) / ranks;
  return 3.0 * (ranks - 1) * m.latency_seconds + remote * m.bytes_per_eval / m.bytes_per_second;
}

}  // namespace

GenerationTime PredictGeneration(const ClusterModel& m, long long population, int ranks) {
  ranks = std::max(ranks, 1);
  GenerationTime t;
  t.seconds_compute = Compute(m, population, ranks);
  t.seconds_communication = Communication(m, population, ranks);
  t.seconds_serial = static_cast<double>(population) * m.serial_seconds_per_eval;
  t.seconds_total = t.seconds_compute + t.seconds_communication + t.seconds_serial;
  const double one_rank = Compute(m, population, 1) + t.seconds_serial;
  t.efficiency = t.seconds_total > 0 ? one_rank / (ranks * t.seconds_total) : 0;
  return t;
}

}  // namespace hexgait
