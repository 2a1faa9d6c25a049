// libFuzzer target: the motor program parser (ParseMotorProgram) against the built-in hexapod on
// arbitrary bytes.
#include "fuzz_inputs.h"

HEXGAIT_FUZZ_TARGET(hexgait::fuzz::ParseMotorProgramInput)
