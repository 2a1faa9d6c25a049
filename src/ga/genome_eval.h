// Genome-keyed conveniences over the simulator's rest-length-keyed entry points: each decodes
// its genomes (ga/genome.h, PerturbedRestLengths) and hands the tables down. For one-off runs
// (simulate, render, tests); a population goes through an Evaluator (eval/evaluator.h).
#pragma once

#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/batch_evaluate.h"
#include "sim/evaluate.h"
#include "sim/step_loop.h"

namespace hexgait {

std::vector<RestLengthTable> PerturbedRestLengths(const CreatureModel& model,
                                                  const MotorProgram& program,
                                                  const std::vector<const Genome*>& genomes);

inline RunResult EvaluateGenome(const CreatureModel& model, const MotorProgram& program,
                                const Genome& genome, const RunOptions& options) {
  return EvaluateRestLengths(model, program, PerturbedRestLengths(model, program, genome), options);
}

inline double LargestStableStep(const CreatureModel& model, const MotorProgram& program,
                                const Genome& genome, const RunOptions& options,
                                int max_halvings = kStableStepHalvings) {
  return LargestStableStep(model, program, PerturbedRestLengths(model, program, genome), options,
                           max_halvings);
}

inline std::vector<RunResult> EvaluateGenomesBatched(const CreatureModel& model,
                                                     const MotorProgram& program,
                                                     const std::vector<const Genome*>& genomes,
                                                     const RunOptions& options, int lanes = 0,
                                                     BatchIsa isa = BatchIsa::kAuto,
                                                     Precision precision = Precision::kDouble) {
  return EvaluateBatched(model, program, PerturbedRestLengths(model, program, genomes), options,
                         lanes, isa, precision);
}

inline std::vector<RunResult> EvaluateGenomesWithCreatureKernel(
    const CreatureModel& model, const MotorProgram& program,
    const std::vector<const Genome*>& genomes, const RunOptions& options) {
  return EvaluateWithCreatureKernel(model, program, PerturbedRestLengths(model, program, genomes),
                                    options);
}

}  // namespace hexgait
