// The paper's genetic algorithm as an optimizer (search/optimizer.h), and Evolve, which runs it
// to the end through the search driver: for benchmarks, sweeps and tests that want a result,
// not a folder.
#pragma once

#include <functional>

#include "eval/evaluator.h"
#include "ga/evolution.h"
#include "search/generational.h"
#include "util/progress.h"

namespace hexgait {

struct EvolutionCallbacks {
  std::function<void(const GenerationStats&, const std::vector<Individual>&)> on_generation;
  Progress on_progress;  // the run's evaluations of its budget
  // After every generation; may throw (for example to stop after a Ctrl-C), which ends the
  // run with the checkpoint already handed out.
  std::function<void(const EvolutionCheckpoint&)> on_checkpoint;
};

// The GA from scratch, or continuing `checkpoint` (same bits as a run never interrupted).
std::unique_ptr<GenerationalOptimizer> MakeGaOptimizer(const SearchScene& scene,
                                                       const EvolutionParams& params);
std::unique_ptr<GenerationalOptimizer> MakeGaOptimizer(const SearchScene& scene,
                                                       const EvolutionCheckpoint& checkpoint);
// The state after the optimizer's last generation (a GA optimizer's only).
EvolutionCheckpoint GaCheckpointOf(const GenerationalOptimizer& ga);

// Runs the GA, evaluating through `evaluator` (which must run params.run; results do not
// depend on which backend it is); with `resume`, continues after its last generation instead of
// starting anew, giving the same bits as an uninterrupted run.
EvolutionResult Evolve(const CreatureModel& model, const MotorProgram& program,
                       const EvolutionParams& params, Evaluator& evaluator,
                       const EvolutionCallbacks& callbacks,
                       const EvolutionCheckpoint* resume = nullptr);

// The same on a local evaluator made from `params` (MakeLocalEvaluator).
EvolutionResult Evolve(const CreatureModel& model, const MotorProgram& program,
                       const EvolutionParams& params, const EvolutionCallbacks& callbacks,
                       const EvolutionCheckpoint* resume = nullptr);

}  // namespace hexgait
