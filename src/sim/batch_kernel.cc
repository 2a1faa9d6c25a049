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
double BatchPeakLoopGeneric(long long iterations, double m, double a);
double BatchPeakLoopAvx2(long long iterations, double m, double a);
double BatchPeakLoopAvx512(long long iterations, double m, double a);
double BatchSqrtDivLoopGeneric(long long iterations, double seed);
double BatchSqrtDivLoopAvx2(long long iterations, double seed);
double BatchSqrtDivLoopAvx512(long long iterations, double seed);

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

int NativeBatchLanes(BatchIsa isa) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  return isa == BatchIsa::kAvx512 ? 8 : isa == BatchIsa::kAvx2 ? 4 : 2;
}

double RunPeakLoop(BatchIsa isa, long long iterations, double m, double a) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  switch (isa) {
    case BatchIsa::kAvx512:
      return BatchPeakLoopAvx512(iterations, m, a);
    case BatchIsa::kAvx2:
      return BatchPeakLoopAvx2(iterations, m, a);
    default:
      return BatchPeakLoopGeneric(iterations, m, a);
  }
}

double RunSqrtDivLoop(BatchIsa isa, long long iterations, double seed) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  switch (isa) {
    case BatchIsa::kAvx512:
      return BatchSqrtDivLoopAvx512(iterations, seed);
    case BatchIsa::kAvx2:
      return BatchSqrtDivLoopAvx2(iterations, seed);
    default:
      return BatchSqrtDivLoopGeneric(iterations, seed);
  }
}

BatchStepFn SelectBatchStep(int lanes, BatchIsa isa) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  if (!BatchIsaSupported(isa))
    throw InputError(BatchIsaName(isa) + " is not supported by this CPU");
  const BatchStepFn* table = isa == BatchIsa::kAvx512 ? BatchStepTableAvx512()
                             : isa == BatchIsa::kAvx2 ? BatchStepTableAvx2()
                                                      : BatchStepTableGeneric();
  for (size_t j = 0; j < std::size(kBatchLaneCounts); ++j) {
    if (kBatchLaneCounts[j] == lanes) return table[j];
  }
  std::string message = "no batched kernel for ";
  message += std::to_string(lanes);
  message += " lanes";
  throw InputError(message);
}

}  // namespace hexgait
