#include "simd/isa.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <string>

#include "util/error.h"

namespace hexgait {

// Defined in batch_kernel_{generic,avx2,avx512}.cc.
const BatchIsaKernels& BatchKernelsGeneric();
const BatchIsaKernels& BatchKernelsAvx2();
const BatchIsaKernels& BatchKernelsAvx512();

std::string PrecisionName(Precision precision) {
  return precision == Precision::kFloat ? "float" : "double";
}

Precision ParsePrecision(const std::string& name) {
  for (Precision p : {Precision::kDouble, Precision::kFloat}) {
    if (name == PrecisionName(p)) return p;
  }
  throw InputError("precision must be 'double' or 'float', got '" + name + "'");
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

int PreferredBatchLanes(BatchIsa isa, Precision precision) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  const int vectors = SelectBatchKernels(isa).vector_registers >= 32 ? 2 : 1;
  return std::min(kMaxBatchLanes, vectors * NativeBatchLanes(isa, precision));
}

const BatchIsaKernels& SelectBatchKernels(BatchIsa isa) {
  if (isa == BatchIsa::kAuto) isa = BestBatchIsa();
  if (!BatchIsaSupported(isa))
    throw InputError(BatchIsaName(isa) + " is not supported by this CPU");
  return isa == BatchIsa::kAvx512 ? BatchKernelsAvx512()
         : isa == BatchIsa::kAvx2 ? BatchKernelsAvx2()
                                  : BatchKernelsGeneric();
}

}  // namespace hexgait
