// libFuzzer target: every optimizer's checkpoint reader (CheckpointKind, then the kind's resume:
// the GA's and CMA-ES's) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseSearchCheckpointInput)
