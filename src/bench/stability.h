// `hexgait bench stability`: stress tests of the integrators.
//  (a) a map of spring stiffness multiplier (every spring, body and legs, damping unchanged)
//      against step size: stable or diverged, and the largest energy reached;
//  (b) energy drift in free flight (bench/free_flight.h: gravity on, ground and damping off);
//  (c) extreme and random genomes with the paper's integrator and step: every run must end as
//      walked, fell or diverged (flagged), never with a silent NaN.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/integrator.h"
#include "util/progress.h"

namespace hexgait {

struct StabilityOptions {
  std::vector<IntegratorKind> integrators = AllIntegrators();
  std::vector<double> stiffness_multipliers = {1, 2, 5, 10, 20, 50, 100};
  std::vector<double> steps = {0.04,    0.02,     0.01,      0.005,     0.0025,
                               0.00125, 0.000625, 0.0003125, 0.00015625};
  double map_duration = 20;  // time units of the unoptimised program per map cell
  // implicit-euler costs ~60x an explicit step; below this step its cells are not run.
  double implicit_min_dt = 0.00125;
  double drift_duration = 1000;
  double drift_dt = 0.0025;
  double drift_sample_interval = 1.0;
  int random_genomes = 1000;
  uint64_t seed = 1;
  int threads = 0;  // genome runs: 0 = all cores
};

struct StabilityCell {
  IntegratorKind integrator = IntegratorKind::kEuler;
  double stiffness_multiplier = 1, dt = 0;
  bool stable = false;
  double max_energy_ratio = 0;  // largest finite E(t) / E(0) seen (sampled every 40 steps)
  double diverge_time = 0;
};

struct DriftSample {
  IntegratorKind integrator = IntegratorKind::kEuler;
  double time = 0;
  double drift = 0;  // (E(t) - E(0)) / initial vibration energy
};

struct GenomeStressRow {
  std::string name;  // "all -8", "all +7", "random"
  int runs = 0, walked = 0, fell = 0, diverged = 0, non_finite = 0;
  double min_distance = 0, max_distance = 0;
};

struct StabilityReport {
  std::vector<StabilityCell> cells;
  std::vector<DriftSample> drift;
  std::vector<GenomeStressRow> genomes;
};

StabilityReport RunStabilityBench(const CreatureModel& model, const MotorProgram& program,
                                  const StabilityOptions& options, const LogLine& note);

std::string StabilityCsv(const StabilityReport& report);    // stability.csv
std::string EnergyDriftCsv(const StabilityReport& report);  // energy_drift.csv
std::string StabilitySummary(const StabilityReport& report);

}  // namespace hexgait
