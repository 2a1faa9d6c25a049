// Fitness evaluations of several genomes at once: the creatures run in lock-step in the lanes
// of the batched kernel (sim/batch_kernel.h). Each result is bit-identical to EvaluateGenome's
// for the same genome: same forces, same controller values, the same fall and divergence checks
// at the same steps, per lane. A lane whose run ends early (divergence, early stop) keeps being
// stepped but its result is frozen at the step where the scalar run would have stopped.
#pragma once

#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/run.h"

namespace hexgait {

// Evaluates `genomes` (at most kMaxBatchLanes) on the calling thread with the explicit Euler
// integrator (options.integrator must be kEuler). `lanes` 0 picks the narrowest kernel that
// holds them all; unused lanes run copies of the first genome and are ignored.
std::vector<RunResult> EvaluateGenomesBatched(const CreatureModel& model,
                                              const MotorProgram& program,
                                              const std::vector<const Genome*>& genomes,
                                              const RunOptions& options, int lanes = 0,
                                              BatchIsa isa = BatchIsa::kAuto);

}  // namespace hexgait
