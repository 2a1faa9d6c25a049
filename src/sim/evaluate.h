// One fitness evaluation: a genome's rest lengths, the creature from rest, the paper's run.
#pragma once

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/run.h"

namespace hexgait {

RunResult EvaluateGenome(const CreatureModel& model, const MotorProgram& program,
                         const Genome& genome, const RunOptions& options);

// The fitness the GA maximises: x-distance, or 0 for a diverged run.
inline double Fitness(const RunResult& r) {
  return r.diverged ? 0.0 : r.distance;
}

}  // namespace hexgait
