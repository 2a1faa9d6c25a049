// The default creature and motor program: the files in assets/ as they were at build time,
// embedded in the binary so `hexgait` runs from any folder.
#pragma once

#include <string>

#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

// Loads `path`, or the embedded default when `path` is empty.
CreatureModel LoadCreatureOrDefault(const std::string& path);
MotorProgram LoadMotorProgramOrDefault(const std::string& path, const CreatureModel& model);

}  // namespace hexgait
