// Backend registration: the one place that decides which Evaluator a process gets.
#include "eval/evaluator.h"

#include "eval/mpi_evaluator.h"

namespace hexgait {

std::unique_ptr<Evaluator> MakeEvaluator(const CreatureModel& model, const MotorProgram& program,
                                         const EvaluatorConfig& config) {
  if (MpiWorldSize() > 1) return MakeMpiEvaluator(model, program, config);
  return MakeLocalEvaluator(model, program, config);
}

}  // namespace hexgait
