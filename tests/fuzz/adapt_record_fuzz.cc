// libFuzzer target: adapt.json's reader (ParseAdaptSummary), which report --adapt uses, on
// arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseAdaptRecordInput)
