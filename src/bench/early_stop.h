// `hexgait bench early-stop`'s measurement: does --early-stop change fitness, and how much would
// stopping a fallen creature early change it? Random genomes, each run for the paper's 1000
// time units with and without early stop, and, for those that fall, the distance they still
// crawl after two more gait cycles.
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>

#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

struct EarlyStopSettings {
  int genomes = 200;  // random genomes of a fixed seed
  int threads = 0;    // 0: all cores
};

struct EarlyStopReport {
  int genomes = 0;
  int fell = 0;           // without early stop
  int stopped_early = 0;  // with it
  double max_fitness_difference = 0;
  double steps_saved_fraction = 0;
  double seconds_without = 0, seconds_with = 0;
  // The distance a fallen creature still covers from two cycles after its fall to the end.
  double crawl_median = 0, crawl_max = 0;
  size_t crawl_runs = 0;
};

EarlyStopReport MeasureEarlyStop(const CreatureModel& model, const MotorProgram& program,
                                 const EarlyStopSettings& settings);

// `hexgait bench early-stop --json`.
nlohmann::json EarlyStopReportJson(const EarlyStopReport& report);

}  // namespace hexgait
