// The data behind the figures, as plain C++: reading an evolve run's files, simulating the two
// programs with a trace, and the CSV text each figure plots (so a user can re-plot it).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "record/run_record.h"
#include "sim/step_loop.h"
#include "sim/trace.h"
#include "util/median.h"
#include "util/progress.h"

namespace hexgait {

// One row of DIR/fitness.csv as 'hexgait evolve' writes it.
struct FitnessRow {
  int generation = 0;
  double best = 0, mean = 0, worst = 0;
};
// Throws InputError naming the file if it is missing, malformed or empty.
std::vector<FitnessRow> ReadFitnessCsv(const std::string& path);
// DIR/run.json's unoptimized.distance, the baseline the fitness figure divides by. Throws
// InputError if it is not positive (a ratio to it would mean nothing).
double ReadUnoptimizedDistance(const RunRecord& run, const std::string& source);

// A program run from rest with a trace sampled every `sample_interval` time units (the first
// sample is the rest pose at t = 0).
struct ProgramTrace {
  std::string name;  // "unoptimized" or "evolved"
  RunResult result;
  std::vector<TraceSample> samples;
};
// `on_chunk(steps_done, steps_total)`, if given, is called every 2^16 steps (a progress bar).
ProgramTrace TraceProgram(const std::string& name, const CreatureModel& model,
                          const MotorProgram& program, const Genome& genome,
                          const RunOptions& options, double sample_interval,
                          const Progress& on_chunk = {});

// A foot on the ground from `start` up to (not including) `end`: the first sample time in
// contact and the first sample time out of contact (or the window's end).
struct ContactInterval {
  int leg = 0;
  double start = 0, end = 0;
};
std::vector<ContactInterval> FootContacts(const std::vector<TraceSample>& samples, int num_legs,
                                          double until);

// Where the motor program commands each leg into its swing position (the position named
// "swing"; none if the program has no such position), at the trace's sample times.
std::vector<ContactInterval> CommandedSwings(const MotorProgram& program, int num_legs,
                                             const std::vector<TraceSample>& samples, double until);

// CSV text behind each figure.
std::string FitnessFigureCsv(const std::vector<FitnessRow>& rows, double unoptimized_distance);
// Several seeds: per generation the median, min and max of each run's best (absolute and as a
// ratio to that run's unoptimized distance). Every run must have the same generations.
struct SeedRun {
  std::string dir;
  std::vector<FitnessRow> rows;
  double unoptimized_distance = 0;
};
std::string FitnessSeedsCsv(const std::vector<SeedRun>& runs);
// Rows "program,kind,leg,leg_name,start,end": kind "contact" per program, and kind "swing"
// (program "motor_program") for the commanded swings.
std::string GaitCsv(const CreatureModel& model, const MotorProgram& program,
                    const std::vector<ProgramTrace>& traces, double until);
// Wide tables, one time column and a group of columns per program, every `stride`-th sample.
std::string BodyCsv(const std::vector<ProgramTrace>& traces, int stride);
std::string PathCsv(const std::vector<ProgramTrace>& traces, int stride);

}  // namespace hexgait
