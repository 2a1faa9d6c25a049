// libFuzzer target: the evolve checkpoint parser (ParseCheckpoint) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseCheckpointInput)
