// The built-in creatures and their motor programs: the files in assets/ as they were at build
// time, embedded in the binary so `hexgait` runs from any folder.
//   hexapod (the default): assets/hexapod.json with assets/metachronal.json
//   wedge (the first design, kept unchanged): assets/wedge.json with assets/wedge_metachronal.json
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

inline constexpr const char* kDefaultCreature = "hexapod";

// "hexapod, wedge": the built-in creature names, the default first.
const std::vector<std::string>& BuiltInCreatureNames();
std::string BuiltInCreatureList();  // the names joined by ", "
bool IsBuiltInCreature(const std::string& name);
// What a run records as its creature: the --creature value, or the default's name when empty.
std::string CreatureLabel(const std::string& creature);

// `creature` is a built-in name, a file path, or empty (the default creature). A value that is
// exactly a built-in name selects the built-in; anything else is read as a file.
CreatureModel LoadCreatureOrDefault(const std::string& creature);
// `path` is a motor program file, or empty: then the built-in program of `creature` (the
// wedge's own program for "wedge"; the default program for the default or a creature file).
MotorProgram LoadMotorProgramOrDefault(const std::string& path, const CreatureModel& model,
                                       const std::string& creature = "");

}  // namespace hexgait
