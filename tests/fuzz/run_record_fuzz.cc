// libFuzzer target: run.json's reader (ParseRunRecord), which sweep and figures use, on arbitrary
// bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseRunRecordInput)
