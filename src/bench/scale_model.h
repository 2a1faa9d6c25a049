// A model of one GA generation's time on a cluster of MPI ranks (docs/scaling.md), fed with
// numbers `hexgait bench scale` measures on this machine. The GA is generational: rank 0 decodes
// the population, sends each rank a contiguous share of rest-length tables, evaluates its own
// share, and waits for every result before selection (the barrier). So a generation costs
//   serial (rank 0 alone) + sends and receives through rank 0's link + the slowest rank's compute.
#pragma once

namespace hexgait {

struct ClusterModel {
  int cores_per_rank = 16;
  // Creatures one core runs for the price of one batch (the SIMD width): a rank's compute comes
  // in rounds of cores_per_rank * lanes creatures, and a round that is not full costs as much.
  int lanes = 8;
  double seconds_per_eval = 0;         // one evaluation's share of a full batch on one core
  double serial_seconds_per_eval = 0;  // rank 0's own work per individual (decoding, selection)
  double bytes_per_eval = 0;           // table out + result back
  double latency_seconds = 2e-6;       // per message
  double bytes_per_second = 10e9;      // rank 0's link
};

struct GenerationTime {
  double seconds_compute = 0;  // the slowest rank
  double seconds_communication = 0;
  double seconds_serial = 0;
  double seconds_total = 0;
  // Time on one rank over `ranks` times the time on `ranks` ranks: 1 is perfect.
  double efficiency = 0;
};

GenerationTime PredictGeneration(const ClusterModel& model, long long population, int ranks);

}  // namespace hexgait
