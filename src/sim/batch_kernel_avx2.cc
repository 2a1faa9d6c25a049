// The batched kernel compiled for one instruction set (flags in CMakeLists.txt); see
// batch_kernel_impl.h.
// Doubles per vector register.
#define HEXGAIT_BATCH_NATIVE_LANES 4
#include "sim/batch_kernel_impl.h"

namespace hexgait {

const BatchIsaKernels& BatchKernelsAvx2() {
  return kKernels;
}

}  // namespace hexgait
