// Rest lengths of the motor springs for every leg position: the paper's geometric
// approximation (each spring's length when the foot sits at its target and nothing else
// moves). The GA perturbs these tables with its genomes (ga/genome.h, PerturbedRestLengths).
#pragma once

#include <vector>

#include "model/creature.h"
#include "motor/motor_program.h"

namespace hexgait {

// rest_length(position, spring) for motor springs; other springs keep the model's value.
struct RestLengthTable {
  int num_springs = 0;
  int num_positions = 0;
  std::vector<double> length;  // [position * num_springs + spring]

  double at(int position, int spring) const { return length[position * num_springs + spring]; }
};

// The foot target of `leg` at `position`, in the rest pose's frame.
Eigen::Vector3d FootTarget(const CreatureModel& model, const MotorProgram& program, int leg,
                           int position);

RestLengthTable GeometricRestLengths(const CreatureModel& model, const MotorProgram& program);

}  // namespace hexgait
