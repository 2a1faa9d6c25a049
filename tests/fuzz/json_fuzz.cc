// libFuzzer target: JSON data file access (ParseJson and every JsonReader accessor) on arbitrary
// bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseJsonInput)
