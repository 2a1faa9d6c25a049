// libFuzzer target: the genome text parser (GenomeFileIsSymmetric, ParseGenome) on arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseGenomeInput)
