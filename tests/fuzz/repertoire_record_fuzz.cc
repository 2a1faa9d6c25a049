// libFuzzer target: repertoire.json's reader (ParseRepertoireRecord), which report reads, on
// arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseRepertoireRecordInput)
