#include "app/assets.h"

#include "embedded_assets.h"
#include "model/creature_io.h"
#include "motor/motor_program_io.h"

namespace hexgait {

CreatureModel LoadCreatureOrDefault(const std::string& path) {
  if (!path.empty()) return LoadCreatureFile(path);
  return ParseCreature(reinterpret_cast<const char*>(kEmbeddedHexapodJson),
                       "assets/hexapod.json (built in)");
}

MotorProgram LoadMotorProgramOrDefault(const std::string& path, const CreatureModel& model) {
  if (!path.empty()) return LoadMotorProgramFile(path, model);
  return ParseMotorProgram(reinterpret_cast<const char*>(kEmbeddedMetachronalJson),
                           "assets/metachronal.json (built in)", model);
}

}  // namespace hexgait
