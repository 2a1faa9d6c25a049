// libFuzzer target: endurance.json's reader (ParseEnduranceRecord) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseEnduranceRecordInput)
