#include "motor/motor_program_io.h"

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {

MotorProgram ParseMotorProgram(const std::string& json_text, const std::string& source,
                               const CreatureModel& model) {
  const nlohmann::json doc = ParseJson(json_text, source);
  const JsonReader root(doc, source, "");
  root.RequireOnlyKeys({"name", "description", "cycle_period", "mirror_time_offset",
                        "gene_length_step", "transition_time", "positions", "instructions"});
  MotorProgram program;
  program.name = root.String("name");
  program.cycle_period = root.PositiveNumber("cycle_period");
  program.mirror_time_offset = root.NonNegativeNumber("mirror_time_offset");
  if (program.mirror_time_offset >= program.cycle_period) {
    root.Child("mirror_time_offset").Fail("must be shorter than cycle_period");
  }
  program.gene_length_step = root.PositiveNumber("gene_length_step");
  program.transition_time = root.NonNegativeNumber("transition_time");

  const JsonReader positions = root.Child("positions");
  const size_t np = positions.ArraySize();
  if (np < 1 || np > 16) positions.Fail("expected 1 to 16 positions, got " + std::to_string(np));
  for (size_t i = 0; i < np; ++i) {
    const JsonReader p = positions.At(i);
    p.RequireOnlyKeys({"name", "foot_offset"});
    LegPosition pos;
    pos.name = p.String("name");
    for (const LegPosition& other : program.positions) {
      if (other.name == pos.name) p.Child("name").Fail("duplicate position '" + pos.name + "'");
    }
    const JsonReader offset = p.Child("foot_offset");
    if (offset.ArraySize() != 3) offset.Fail("expected [forward, outward, up]");
    pos.foot_offset = {offset.At(0).AsNumber(), offset.At(1).AsNumber(), offset.At(2).AsNumber()};
    program.positions.push_back(pos);
  }

  const JsonReader instructions = root.Child("instructions");
  if (instructions.ArraySize() == 0) instructions.Fail("the program has no instructions");
  for (size_t i = 0; i < instructions.ArraySize(); ++i) {
    const JsonReader in = instructions.At(i);
    in.RequireOnlyKeys({"time", "leg", "position"});
    Instruction instruction;
    instruction.time = in.NonNegativeNumber("time");
    if (instruction.time >= program.cycle_period) {
      in.Child("time").Fail("must be below cycle_period " + std::to_string(program.cycle_period));
    }
    const std::string leg = in.String("leg");
    instruction.leg = model.LegIndex(leg);
    if (instruction.leg < 0) in.Child("leg").Fail("the creature has no leg named '" + leg + "'");
    const std::string position = in.String("position");
    for (size_t p = 0; p < program.positions.size(); ++p) {
      if (program.positions[p].name == position) instruction.position = static_cast<int>(p);
    }
    if (instruction.position < 0) in.Child("position").Fail("no position named '" + position + "'");
    program.instructions.push_back(instruction);
  }
  ExpandMotorProgram(program, model, source);
  return program;
}

MotorProgram LoadMotorProgramFile(const std::string& path, const CreatureModel& model) {
  return ParseMotorProgram(ReadTextFile(path), path, model);
}

}  // namespace hexgait
