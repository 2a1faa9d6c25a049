// Backend registration: the one place that decides which Evaluator a process gets; and the
// check of the settings every backend takes.
#include "eval/evaluator.h"

#include "eval/mpi_evaluator.h"
#include "util/error.h"

namespace hexgait {

EvaluationStopped::EvaluationStopped(int done_count, int total_count)
    : Stopped("the population under way was dropped (" + std::to_string(done_count) + " of " +
              std::to_string(total_count) + " simulations run)"),
      done(done_count),
      total(total_count) {}

void CheckEvaluatorConfig(const EvaluatorConfig& config) {
  if (config.threads < 0 || config.threads > 1024) {
    throw InputError("--threads must be in [0, 1024]");
  }
  if (config.batch_lanes < 0 || config.batch_lanes > kMaxBatchLanes) {
    throw InputError("--batch-lanes must be in [0, " + std::to_string(kMaxBatchLanes) + "]");
  }
  if (config.precision == Precision::kFloat && config.run.integrator != IntegratorKind::kEuler) {
    throw InputError("--precision float needs --integrator euler");
  }
}

std::unique_ptr<Evaluator> MakeEvaluator(const CreatureModel& model, const MotorProgram& program,
                                         const EvaluatorConfig& config) {
  if (MpiWorldSize() > 1) return MakeMpiEvaluator(model, program, config);
  return MakeLocalEvaluator(model, program, config);
}

}  // namespace hexgait
