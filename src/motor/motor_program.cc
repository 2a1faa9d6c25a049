#include "motor/motor_program.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace hexgait {

void ExpandMotorProgram(MotorProgram& program, const CreatureModel& model,
                        const std::string& source) {
  auto fail = [&](const std::string& what) { throw InputError(source + ": " + what); };
  const int num_legs = static_cast<int>(model.legs.size());
  std::vector<int> count(num_legs, 0);
  std::vector<bool> position_used(program.positions.size(), false);
  for (const Instruction& in : program.instructions) {
    ++count[in.leg];
    position_used[in.position] = true;
  }
  for (size_t p = 0; p < position_used.size(); ++p) {
    if (!position_used[p]) fail("position '" + program.positions[p].name + "' is never used");
  }
  program.expanded = program.instructions;
  for (int leg = 0; leg < num_legs; ++leg) {
    const int mirror = model.legs[leg].mirror;
    if (count[leg] > 0 && count[mirror] > 0) {
      fail("legs '" + model.legs[leg].name + "' and '" + model.legs[mirror].name +
           "' both have instructions; write one side, the other replays it mirrored");
    }
    if (count[leg] == 0 && count[mirror] == 0) {
      fail("leg '" + model.legs[leg].name + "' has no instructions (nor has its mirror)");
    }
  }
  for (const Instruction& in : program.instructions) {
    Instruction m = in;
    m.leg = model.legs[in.leg].mirror;
    m.time = std::fmod(in.time + program.mirror_time_offset, program.cycle_period);
    program.expanded.push_back(m);
  }
  std::stable_sort(program.expanded.begin(), program.expanded.end(),
                   [](const Instruction& a, const Instruction& b) { return a.time < b.time; });
}

std::vector<int> LegPositionsAt(const MotorProgram& program, int num_legs, double time) {
  std::vector<int> position(num_legs, -1);
  if (time < 0) return position;
  // Before the first pass through the cycle ends, legs not yet instructed keep the rest pose.
  const double phase = std::fmod(time, program.cycle_period);
  const bool first_cycle = time < program.cycle_period;
  for (const Instruction& in : program.expanded) {
    if (in.time <= phase) position[in.leg] = in.position;
  }
  if (!first_cycle) {
    // Legs whose last instruction in the cycle lies after `phase` still hold it from the
    // previous cycle.
    for (int leg = 0; leg < num_legs; ++leg) {
      if (position[leg] >= 0) continue;
      for (const Instruction& in : program.expanded) {
        if (in.leg == leg) position[leg] = in.position;
      }
    }
  }
  return position;
}

}  // namespace hexgait
