// hexgait bench's measurements as requests: each is one call that makes every check (ranges,
// inputs and outputs, the scene, the long-run estimate) before it measures, and returns the
// report of src/bench with the files it wrote. The commands (src/app/cmd_bench_*.cc) parse flags
// into these structs and print the report.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bench/accuracy.h"
#include "bench/early_stop.h"
#include "bench/movie_bench.h"
#include "bench/scale_report.h"
#include "bench/speed.h"
#include "bench/stability.h"
#include "run/movie_request.h"
#include "run/scene.h"
#include "sim/integrator.h"

namespace hexgait {

// A line about where a long measurement is ("evolving the 'evolved' program"); the command
// prints it on stderr.

// What the integrator benchmarks share: where their CSV files go, the small version for tests,
// the integrators and the creature.
struct BenchFolderRequest {
  std::string out_dir = "out/bench";
  bool quick = false;
  std::string integrators;  // comma-separated; empty: all
  std::string creature;     // a built-in name or a creature file; empty: the default
};

// "a,b" -> integrators; empty -> all. Throws InputError on an unknown name.
std::vector<IntegratorKind> ParseIntegratorList(const std::string& text);

struct AccuracyRequest {
  BenchFolderRequest common;
  std::string genome_path;  // the 'evolved' program; empty: evolve one (seed 1, the paper's)
  bool full = false;        // implicit Euler on the whole ladder too
  double reference_tolerance = 1e-10;
};
struct AccuracyResult {
  AccuracyReport report;
  std::string csv_path;
};
AccuracyResult MeasureAccuracyToFolder(const AccuracyRequest& request, const LogLine& note);

struct StabilityRequest {
  BenchFolderRequest common;
  int genomes = 1000;
  uint64_t seed = 1;
  int threads = 0;
};
struct StabilityResult {
  StabilityReport report;
  std::string stability_csv, drift_csv;
};
StabilityResult MeasureStabilityToFolder(const StabilityRequest& request, const LogLine& note);

struct SpeedRequest {
  SpeedSettings settings;
  bool time_paper_experiment = true;  // hexgait evolve --seed 1, whole
};
SpeedReport MeasureSpeedOfPaths(const SpeedRequest& request);

EarlyStopReport MeasureEarlyStopOf(const EarlyStopSettings& settings);

struct ScaleRequest {
  SceneOptions scene;
  std::string ranks = "1,2,4";
  int population = 1024;
  int generations = 3;
  double time = 100;
  int threads = 0;
  std::string precision = "double";
  uint64_t seed = 1;
  std::string mpirun = "mpirun";
  // The cluster the model predicts for.
  int model_cores = 16;
  double model_time = 1000;
  double latency_us = 2;
  double bandwidth_gbs = 10;
  std::string model_ranks = "64,1024";
  long long model_evaluations = 0;
};
// On one process: measures on 1 rank, then on each other rank count by launching this binary
// again as `mpirun -np N hexgait bench scale ...` (skipped, and said in the report, without
// mpirun or MPI), and fits the cluster model. Launched so, under mpirun: rank 0 measures its
// rank count alone (`measured_alone` set) while the other ranks serve its evaluations.
struct ScaleResult {
  bool measured_alone = false;
  ScaleMeasurement measurement;  // when measured_alone
  ScaleReport report;            // otherwise
};
ScaleResult MeasureScaling(const ScaleRequest& request, const LogLine& note);

struct MovieBenchRequest {
  SceneOptions scene;
  GenomeChoice genome;
  MovieRequest movie;
  int repeats = 3;
  std::string out_dir = "out/bench";  // for the scratch movies, removed afterwards
  bool ffmpeg = true;                 // compare with the ffmpeg tool, when in PATH
  bool memory = true;                 // peak memory of whole `hexgait render` runs
};
MovieBenchReport MeasureMovieCost(const MovieBenchRequest& request, const LogLine& note);

}  // namespace hexgait
