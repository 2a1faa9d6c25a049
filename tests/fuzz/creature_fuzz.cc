// libFuzzer target: the creature asset parser (ParseCreature) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseCreatureInput)
