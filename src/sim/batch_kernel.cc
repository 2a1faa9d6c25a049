#include "sim/batch_kernel.h"

#include <cstdlib>
#include <iterator>
#include <string>

#include "util/error.h"

namespace hexgait {

// Defined in batch_kernel_{generic,avx2,avx512}.cc.
const BatchStepFn* BatchStepTableGeneric();
const BatchStepFn* BatchStepTableAvx2();
const BatchStepFn* BatchStepTableAvx512();
const BatchStepFnF* BatchStepTableFloatGeneric();
const BatchStepFnF* BatchStepTableFloatAvx2();
const BatchStepFnF* BatchStepTableFloatAvx512();
double BatchPeakLoopGeneric(long long iterations, double m, double a);
double BatchPeakLoopAvx2(long long iterations, double m, double a);
double BatchPeakLoopAvx512(long long iterations, double m, double a);
double BatchPeakLoopFloatGeneric(long long iterations, float m, float a);
double BatchPeakLoopFloatAvx2(long long iterations, float m, float a);
double BatchPeakLoopFloatAvx512(long long iterations, float m, float a);
double BatchSqrtDivLoopGeneric(long long iterations, double seed);
double BatchSqrtDivLoopAvx2(long long iterations, double seed);
double BatchSqrtDivLoopAvx512(long long iterations, double seed);
double BatchSqrtDivLoopFloatGeneric(long long iterations, float seed);
double BatchSqrtDivLoopFloatAvx2(long long iterations, float seed);
double BatchSqrtDivLoopFloatAvx512(long long iterations, float seed);

std::string PrecisionName(Precision precision) {
  return precision == Precision::kFloat ? "float" : "double";
}

int BatchLanesFor(int creatures) {
  for (int lanes : kBatchLaneCounts) {
    if (lanes >= creatures) return lanes;
  }
  return kMaxBatchLanes;
}

std::string BatchIsaName(BatchIsa isa) {
  switch (isa) {
    case BatchIsa::kAuto:
      return BatchIsaName(BestBatchIsa());
    case BatchIsa::kGeneric:
      return "x86-64";
    case BatchIsa::kAvx2:
      return "avx2";
    case BatchIsa::kAvx512:
      return "avx512";
  }
  return "?";
}

bool BatchIsaSupported(BatchIsa isa) {
  switch (isa) {
    case BatchIsa::kAuto:
    case BatchIsa::kGeneric:
      return true;
    case BatchIsa::kAvx2:
      return __builtin_cpu_supports("avx2");
    case BatchIsa::kAvx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
             __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw");
  }
  return false;
}

BatchIsa BestBatchIsa() {
  // Valgrind cannot run AVX-512: HEXGAIT_BATCH_ISA=avx2 (or x86-64) caps the choice, for
  // callgrind instruction counts and for testing the other kernels on this machine.
  static const BatchIsa best = [] {
    BatchIsa cap = BatchIsa::kAvx512;
    if (const char* env = std::getenv("HEXGAIT_BATCH_ISA")) {
      const std::string name = env;
      if (name == "x86-64") cap = BatchIsa::kGeneric;
      if (name == "avx2") cap = BatchIsa::kAvx2;
    }
    for (BatchIsa isa : {BatchIsa::kAvx512, BatchIsa::kAvx2}) {
      if (isa <= cap && BatchIsaSupported(isa)) return isa;
    }
    return BatchIsa::kGeneric;
  }();
  return best;
}

int NativeBatchLanes(BatchIsa isa, Precision precision) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  const int doubles = isa == BatchIsa::kAvx512 ? 8 : isa == BatchIsa::kAvx2 ? 4 : 2;
  return precision == Precision::kFloat ? 2 * doubles : doubles;
}

double RunPeakLoop(BatchIsa isa, long long iterations, double m, double a, Precision precision) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  const bool f = precision == Precision::kFloat;
  const float mf = static_cast<float>(m), af = static_cast<float>(a);
  switch (isa) {
    case BatchIsa::kAvx512:
      return f ? BatchPeakLoopFloatAvx512(iterations, mf, af)
               : BatchPeakLoopAvx512(iterations, m, a);
    case BatchIsa::kAvx2:
      return f ? BatchPeakLoopFloatAvx2(iterations, mf, af) : BatchPeakLoopAvx2(iterations, m, a);
    default:
      return f ? BatchPeakLoopFloatGeneric(iterations, mf, af)
               : BatchPeakLoopGeneric(iterations, m, a);
  }
}

double RunSqrtDivLoop(BatchIsa isa, long long iterations, double seed, Precision precision) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  const bool f = precision == Precision::kFloat;
  const float sf = static_cast<float>(seed);
  switch (isa) {
    case BatchIsa::kAvx512:
      return f ? BatchSqrtDivLoopFloatAvx512(iterations, sf)
               : BatchSqrtDivLoopAvx512(iterations, seed);
    case BatchIsa::kAvx2:
      return f ? BatchSqrtDivLoopFloatAvx2(iterations, sf) : BatchSqrtDivLoopAvx2(iterations, seed);
    default:
      return f ? BatchSqrtDivLoopFloatGeneric(iterations, sf)
               : BatchSqrtDivLoopGeneric(iterations, seed);
  }
}

namespace {
template <class T>
const BatchStepFnT<T>* StepTable(BatchIsa isa) {
  if constexpr (sizeof(T) == sizeof(float)) {
    return isa == BatchIsa::kAvx512 ? BatchStepTableFloatAvx512()
           : isa == BatchIsa::kAvx2 ? BatchStepTableFloatAvx2()
                                    : BatchStepTableFloatGeneric();
  } else {
    return isa == BatchIsa::kAvx512 ? BatchStepTableAvx512()
           : isa == BatchIsa::kAvx2 ? BatchStepTableAvx2()
                                    : BatchStepTableGeneric();
  }
}
}  // namespace

template <class T>
BatchStepFnT<T> SelectBatchStepT(int lanes, BatchIsa isa) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  if (!BatchIsaSupported(isa))
    throw InputError(BatchIsaName(isa) + " is not supported by this CPU");
  const BatchStepFnT<T>* table = StepTable<T>(isa);
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
