// The batched kernel compiled for one instruction set (flags in CMakeLists.txt); see
// batch_kernel_impl.h.
// Doubles per vector register.
#define HEXGAIT_BATCH_NATIVE_LANES 2
#include "sim/batch_kernel_impl.h"

namespace hexgait {

const BatchStepFn* BatchStepTableGeneric() {
  return kStepTable<double>;
}
const BatchStepFnF* BatchStepTableFloatGeneric() {
  return kStepTable<float>;
}

double BatchPeakLoopGeneric(long long iterations, double m, double a) {
  return PeakLoop<double>(iterations, m, a);
}
double BatchPeakLoopFloatGeneric(long long iterations, float m, float a) {
  return PeakLoop<float>(iterations, m, a);
}

double BatchSqrtDivLoopGeneric(long long iterations, double seed) {
  return SqrtDivLoop<double>(iterations, seed);
}
double BatchSqrtDivLoopFloatGeneric(long long iterations, float seed) {
  return SqrtDivLoop<float>(iterations, seed);
}

}  // namespace hexgait
