#include "sim/batch_kernel.h"

#include "util/error.h"

namespace hexgait {

double RunPeakLoop(BatchIsa isa, long long iterations, double m, double a, Precision precision) {
  const BatchIsaKernels& k = SelectBatchKernels(isa);
  return precision == Precision::kFloat
             ? k.peak_loop_float(iterations, static_cast<float>(m), static_cast<float>(a))
             : k.peak_loop(iterations, m, a);
}

int PeakLoopFlops(BatchIsa isa, Precision precision) {
  return 2 * SelectBatchKernels(isa).peak_loop_chains * NativeBatchLanes(isa, precision);
}

double RunSqrtDivLoop(BatchIsa isa, long long iterations, double seed, Precision precision) {
  const BatchIsaKernels& k = SelectBatchKernels(isa);
  return precision == Precision::kFloat
             ? k.sqrt_div_loop_float(iterations, static_cast<float>(seed))
             : k.sqrt_div_loop(iterations, seed);
}

template <class T>
BatchStepFnT<T> SelectBatchStepT(int lanes, BatchIsa isa) {
  const BatchIsaKernels& k = SelectBatchKernels(isa);
  const BatchStepFnT<T>* table;
  if constexpr (sizeof(T) == sizeof(float)) {
    table = k.step_float;
  } else {
    table = k.step;
  }
  for (size_t j = 0; j < std::size(kBatchLaneCounts); ++j) {
    if (kBatchLaneCounts[j] == lanes) return table[j];
  }
  std::string message = "no batched kernel for ";
  message += std::to_string(lanes);
  message += " lanes";
  throw InputError(message);
}

template BatchStepFnT<double> SelectBatchStepT<double>(int lanes, BatchIsa isa);
template BatchStepFnT<float> SelectBatchStepT<float>(int lanes, BatchIsa isa);

}  // namespace hexgait
