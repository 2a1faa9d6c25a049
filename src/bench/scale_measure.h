// `hexgait bench scale`'s measurement: generations of random genomes evaluated through the
// evaluation seam on however many MPI ranks this process runs with (one without mpirun), with
// each generation's time split into rank 0's decoding, sending, the ranks' compute and the rest
// (communication and waiting).
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "eval/evaluator.h"
#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

struct ScaleSettings {
  EvaluatorConfig evaluator;  // run options, threads per rank, precision
  int population = 1024;
  int generations = 3;
  uint64_t seed = 1;
};

struct ScaleGeneration {
  double seconds_decode = 0;        // rank 0: making the genomes and their tables
  double seconds_evaluate = 0;      // rank 0: the Evaluate call, all ranks together
  double seconds_send = 0;          // rank 0: handing out the tables
  double seconds_compute_max = 0;   // the slowest rank's evaluation
  double seconds_compute_mean = 0;  // the mean over ranks (the gap to max is imbalance)
  // The Evaluate call less the slowest rank's compute: sends, receives and waiting.
  double seconds_communication = 0;
  long long bytes = 0;  // sent and received by rank 0
};

struct ScaleMeasurement {
  int ranks = 1;
  int threads_per_rank = 1;  // the evaluator's threads on each rank
  std::vector<ScaleGeneration> generations;
};

// Rank 0 (or the only process): measures. On the other ranks the MPI evaluator it makes serves
// rank 0 and ends the command (MpiWorkerDone).
ScaleMeasurement MeasureScale(const CreatureModel& model, const MotorProgram& program,
                              const ScaleSettings& settings);

// A measurement as rank 0 of `mpirun -np N hexgait bench scale` prints it for the command that
// launched it, and read back there (throws nlohmann::json::exception on a malformed one).
nlohmann::json ScaleMeasurementJson(const ScaleMeasurement& m);
ScaleMeasurement ScaleMeasurementFromJson(const nlohmann::json& j);

}  // namespace hexgait
