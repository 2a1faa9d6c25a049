// One fitness evaluation: a rest-length table (the GA decodes its genomes into these,
// ga/genome.h), the creature from rest, the paper's run.
#pragma once

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "sim/step_loop.h"

namespace hexgait {

RunResult EvaluateRestLengths(const CreatureModel& model, const MotorProgram& program,
                              const RestLengthTable& table, const RunOptions& options);

inline constexpr int kStableStepHalvings = 4;

// After a diverged run: reruns the same evaluation with dt halved, up to `max_halvings` times,
// and returns the first (largest) step that runs the whole duration without diverging, or 0
// if none does. Costs up to 2 + 4 + ... + 2^max_halvings times the original run.
double LargestStableStep(const CreatureModel& model, const MotorProgram& program,
                         const RestLengthTable& table, RunOptions options,
                         int max_halvings = kStableStepHalvings);

// The fitness the GA maximises: x-distance, or 0 for a diverged run.
inline double Fitness(const RunResult& r) {
  return r.diverged ? 0.0 : r.distance;
}

}  // namespace hexgait
