#include "motor/assets.h"

#include <filesystem>
#include <system_error>

#include "embedded_assets.h"
#include "model/creature_io.h"
#include "motor/motor_program_io.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct BuiltIn {
  const char* name;
  const unsigned char* creature;
  const char* creature_file;
  const unsigned char* program;
  const char* program_file;
};

constexpr BuiltIn kBuiltIns[] = {
    {"hexapod", kEmbeddedHexapodJson, "assets/hexapod.json", kEmbeddedMetachronalJson,
     "assets/metachronal.json"},
    {"wedge", kEmbeddedWedgeJson, "assets/wedge.json", kEmbeddedWedgeMetachronalJson,
     "assets/wedge_metachronal.json"},
};

const BuiltIn* FindBuiltIn(const std::string& creature) {
  const std::string name = creature.empty() ? kDefaultCreature : creature;
  for (const BuiltIn& b : kBuiltIns) {
    if (name == b.name) return &b;
  }
  return nullptr;
}

const char* Text(const unsigned char* bytes) {
  return reinterpret_cast<const char*>(bytes);
}

}  // namespace

const std::vector<std::string>& BuiltInCreatureNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const BuiltIn& b : kBuiltIns) v.emplace_back(b.name);
    return v;
  }();
  return names;
}

std::string BuiltInCreatureList() {
  std::string list;
  for (const std::string& name : BuiltInCreatureNames()) {
    list += (list.empty() ? "" : ", ") + name;
  }
  return list;
}

bool IsBuiltInCreature(const std::string& name) {
  return !name.empty() && FindBuiltIn(name) != nullptr;
}

std::string CreatureLabel(const std::string& creature) {
  return creature.empty() ? kDefaultCreature : creature;
}

CreatureModel LoadCreatureOrDefault(const std::string& creature) {
  if (const BuiltIn* b = FindBuiltIn(creature)) {
    return ParseCreature(Text(b->creature), std::string(b->creature_file) + " (built in)");
  }
  std::error_code ec;
  if (!std::filesystem::exists(creature, ec)) {
    throw FileError("--creature '" + creature + "': no such file, and not a built-in creature (" +
                    BuiltInCreatureList() + ")");
  }
  return LoadCreatureFile(creature);
}

MotorProgram LoadMotorProgramOrDefault(const std::string& path, const CreatureModel& model,
                                       const std::string& creature) {
  if (!path.empty()) return LoadMotorProgramFile(path, model);
  const BuiltIn* b = FindBuiltIn(creature);
  if (b == nullptr) b = &kBuiltIns[0];  // a creature file: the default program, as before
  return ParseMotorProgram(Text(b->program), std::string(b->program_file) + " (built in)", model);
}

}  // namespace hexgait
