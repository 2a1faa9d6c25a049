// The open-loop motor program: a fixed list of (time, leg, position) instructions that loops
// every cycle, and the six leg positions as foot targets. Learning never changes the sequence,
// only the rest lengths each position gives the leg springs (see ga/genome.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/creature.h"

namespace hexgait {

struct LegPosition {
  std::string name;
  // Foot target relative to the foot's rest position: x forward, y outward (away from the
  // body's midline, so one table serves both sides), z up.
  Eigen::Vector3d foot_offset = Eigen::Vector3d::Zero();
};

struct Instruction {
  double time = 0;  // within the cycle, [0, cycle_period)
  int leg = -1;     // index into CreatureModel::legs
  int position = -1;
};

struct MotorProgram {
  std::string name;
  double cycle_period = 66.0;  // the loop instruction: jump back to the start after this time
  // Bilateral symmetry: legs without instructions of their own replay their mirror leg's
  // instructions this much later (half a cycle for the metachronal wave).
  double mirror_time_offset = 33.0;
  double gene_length_step = 0.01;  // rest-length change per unit of a gene
  // An instruction changes a leg's commanded rest lengths at one moment; the springs' rest
  // lengths then travel there linearly over this time (an actuator's finite speed; 0 = jump).
  double transition_time = 0.0;
  std::vector<LegPosition> positions;
  std::vector<Instruction> instructions;  // as written in the file (one side)

  // Derived: every leg's instructions (the written ones plus the mirrored ones), sorted by time.
  std::vector<Instruction> expanded;

  int num_positions() const { return static_cast<int>(positions.size()); }
  // Instructions as written plus the loop back to the start, the paper's count (19).
  int num_written_instructions() const { return static_cast<int>(instructions.size()) + 1; }
};

// Builds `expanded` and checks every leg gets instructions. Throws InputError naming `source`.
void ExpandMotorProgram(MotorProgram& program, const CreatureModel& model,
                        const std::string& source);

// The leg positions each leg is in at time t (mod cycle), -1 before its first instruction.
std::vector<int> LegPositionsAt(const MotorProgram& program, int num_legs, double time);

}  // namespace hexgait
