// libFuzzer target: the repertoire's archive parser (ParseArchive) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseArchiveInput)
