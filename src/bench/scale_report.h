// `hexgait bench scale`'s whole measurement: one large population's generations on 1, 2, 4...
// MPI ranks of this machine, each generation's time split into compute and communication, and
// the cluster model of docs/scaling.md fed with those measurements. One rank is measured in this
// process; more ranks through a function the caller hands in (the command re-runs itself under
// mpirun, whose rank 0 prints ScaleMeasurementJson).
#pragma once

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "bench/scale_measure.h"
#include "bench/scale_model.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "util/progress.h"

namespace hexgait {

struct ScaleBenchSettings {
  // One rank count's measurement: run options, threads per rank, precision, population,
  // generations, seed.
  ScaleSettings measure;
  std::vector<int> ranks = {1, 2, 4};  // rank counts to measure, ascending; 1 always is
  double time = 100;                   // simulated time per evaluation (measure's run duration)
  // The cluster the model predicts for.
  int model_cores = 16;
  double model_time = 1000;
  double latency_us = 2;
  double bandwidth_gbs = 10;
  std::vector<int> model_ranks = {64, 1024};  // rank counts the model predicts for
  // A whole search of this many evaluations, in generations (or batches) of each predicted
  // population: ceil(evaluations / population) generations. 0: not predicted.
  long long model_evaluations = 0;
};

// One rank count's medians over its generations, and what the table shows of them.
struct ScaleRow {
  int ranks = 1, threads = 1;
  double evaluate = 0, compute_max = 0, compute_mean = 0, communication = 0, send = 0, decode = 0,
         bytes = 0;
  double evaluations_per_second = 0;
  double seconds_generation = 0;  // evaluate + decode
  double speedup = 0;             // against the first (one-rank) row
  bool oversubscribed = false;    // more ranks x threads than this machine's cores
};

struct ScalePrediction {
  int ranks = 0;
  long long population = 0;
  GenerationTime time;
  double seconds_search = 0;  // model_evaluations in generations of `population`; 0: not asked
};

struct ScaleReport {
  std::string cpu;
  int cores = 1;     // this machine's hardware threads
  bool mpi = false;  // whether rank counts above 1 could be measured
  int population = 0, generations = 0;
  double time_units = 0;
  std::string precision;
  std::vector<ScaleRow> rows;  // measured, ascending rank counts, the one-rank row first
  std::vector<int> skipped;    // rank counts not measured (no MPI)
  ClusterModel model;
  double model_time = 0, latency_us = 0, bandwidth_gbs = 0;
  std::vector<int> cluster_ranks;                    // the rank counts predicted for
  std::vector<long long> cluster_populations;        // the populations predicted for
  std::vector<ScalePrediction> predicted;            // for each of cluster_ranks, each population
  std::vector<long long> population_for_90_percent;  // for each of cluster_ranks; -1: none
  long long model_evaluations = 0;                   // settings.model_evaluations
};

// Measures one rank in this process and each other rank count of `settings.ranks` with
// `on_ranks` (empty: those are skipped), then fits and runs the cluster model. `note` hears
// a line before each rank count. Throws Stopped when a stop is requested between rank counts.
ScaleReport MeasureScaleAcrossRanks(const CreatureModel& model, const MotorProgram& program,
                                    const ScaleBenchSettings& settings,
                                    const std::function<ScaleMeasurement(int ranks)>& on_ranks,
                                    const LogLine& note = {});

// `hexgait bench scale --json`.
nlohmann::json ScaleReportJson(const ScaleReport& report);

}  // namespace hexgait
