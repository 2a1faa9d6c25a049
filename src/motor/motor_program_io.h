// Loading a motor program from JSON (assets/metachronal.json).
#pragma once

#include <string>

#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

MotorProgram ParseMotorProgram(const std::string& json_text, const std::string& source,
                               const CreatureModel& model);
MotorProgram LoadMotorProgramFile(const std::string& path, const CreatureModel& model);

}  // namespace hexgait
