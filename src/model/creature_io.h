// Loading a creature from its JSON description (assets/hexapod.json).
#pragma once

#include <string>

#include "model/creature.h"

namespace hexgait {

// Parses and validates; `source` names the file in error messages.
CreatureModel ParseCreature(const std::string& json_text, const std::string& source);
CreatureModel LoadCreatureFile(const std::string& path);

}  // namespace hexgait
