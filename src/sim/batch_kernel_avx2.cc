// The batched kernel compiled for one instruction set (flags in CMakeLists.txt); see
// batch_kernel_impl.h.
// Doubles per vector register.
#define HEXGAIT_BATCH_NATIVE_LANES 4
#include "sim/batch_kernel_impl.h"

namespace hexgait {

const BatchStepFn* BatchStepTableAvx2() {
  return kStepTable<double>;
}
const BatchStepFnF* BatchStepTableFloatAvx2() {
  return kStepTable<float>;
}

double BatchPeakLoopAvx2(long long iterations, double m, double a) {
  return PeakLoop<double>(iterations, m, a);
}
double BatchPeakLoopFloatAvx2(long long iterations, float m, float a) {
  return PeakLoop<float>(iterations, m, a);
}

double BatchSqrtDivLoopAvx2(long long iterations, double seed) {
  return SqrtDivLoop<double>(iterations, seed);
}
double BatchSqrtDivLoopFloatAvx2(long long iterations, float seed) {
  return SqrtDivLoop<float>(iterations, seed);
}

}  // namespace hexgait
