// A build without MPI: one rank, never launched by mpirun (eval/mpi_evaluator.h).
#include "eval/mpi_evaluator.h"
#include "util/error.h"

namespace hexgait {

bool MpiBuiltIn() {
  return false;
}

void MpiInitIfLaunched(int*, char***) {}
void MpiFinalize() {}
void MpiAbort(int) {}
int MpiWorldSize() {
  return 1;
}
int MpiRank() {
  return 0;
}

std::unique_ptr<Evaluator> MakeMpiEvaluator(const CreatureModel&, const MotorProgram&,
                                            const EvaluatorConfig&, MpiTimings*) {
  throw InputError("this hexgait was built without MPI");
}

void ServeMpiEvaluations(const CreatureModel&, const MotorProgram&, const EvaluatorConfig&) {
  throw InputError("this hexgait was built without MPI");
}

}  // namespace hexgait
