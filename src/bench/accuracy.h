// `hexgait bench accuracy`: run time against error. Every integrator on a ladder of steps, for
// the unoptimised and an evolved program, against the adaptive reference (sim/reference.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/integrator.h"
#include "util/progress.h"

namespace hexgait {

struct AccuracyProgram {
  std::string name;  // "unoptimized" or "evolved"
  Genome genome;
};

struct AccuracyOptions {
  std::vector<IntegratorKind> integrators = AllIntegrators();
  std::vector<double> steps;  // the dt ladder, largest first
  // implicit-euler costs ~60x an explicit step (a 42x42 LU per step): by default it stops at
  // this step so the bench runs in minutes; 0 runs the whole ladder.
  double implicit_min_dt = 0.0025;
  double duration = 1000;     // fitness horizon (time units)
  double short_horizon = 10;  // first position-error time
  double reference_tolerance = 1e-10;
  // Also run explicit Euler in float lanes (sim/batch_evaluate.h), as the rows "euler-float",
  // when euler is among `integrators`.
  bool float_lanes = true;
};

// The default ladder: 0.01 (4x the paper's step) halving down to 0.0025 / 16.
std::vector<double> DefaultStepLadder();

struct AccuracyRow {
  IntegratorKind integrator = IntegratorKind::kEuler;
  Precision precision = Precision::kDouble;  // kFloat: the batched kernel's float lanes
  std::string program;
  double dt = 0;
  bool stable = false;
  double pos_error_t10 = 0;     // max over particles of |x - x_ref| at short_horizon
  double pos_error_cycle1 = 0;  // the same at the end of the first gait cycle
  double fitness = 0;           // x-distance after `duration`
  double fitness_rel_error = 0;
  // Seconds of one core per 1000 time units: the run's thread CPU time, which equals its wall
  // time on an idle core and is not inflated when other processes share the machine.
  double wall_s_per_1000tu = 0;
};

// What the reference is and how much its tolerance matters: the same quantities with the
// tolerance halved.
struct ReferenceReport {
  std::string program;
  double fitness = 0;
  long long steps = 0;
  double wall_s = 0;
  double halving_change_t10 = 0, halving_change_cycle1 = 0, halving_change_fitness_rel = 0;
};

struct AccuracyReport {
  double cycle_time = 0;  // end of the first gait cycle
  std::vector<ReferenceReport> references;
  std::vector<AccuracyRow> rows;
};

AccuracyReport RunAccuracyBench(const CreatureModel& model, const MotorProgram& program,
                                const std::vector<AccuracyProgram>& programs,
                                const AccuracyOptions& options, const LogLine& note);

// The row's method: the integrator's name, with "-float" for float lanes.
std::string MethodName(const AccuracyRow& row);

// accuracy.csv: integrator,program,dt,stable,pos_error_t10,pos_error_cycle1,fitness,
// fitness_rel_error,wall_s_per_1000tu (errors empty for unstable runs).
std::string AccuracyCsv(const AccuracyReport& report);
// The table printed on stdout, the reference summary, and for each program which integrator
// and step reach explicit Euler's error at the paper's step fastest.
std::string AccuracySummary(const AccuracyReport& report);

}  // namespace hexgait
