// Derivatives of the total force (forces.h) with respect to positions and velocities, for the
// linearised implicit integrator: 3N x 3N matrices, particle i's x, y, z at rows 3i..3i+2.
#pragma once

#include <Eigen/Core>

#include "model/creature.h"
#include "sim/forces.h"

namespace hexgait {

// Writes K = d f / d x and D = d f / d v at the given state. Both must already be 3N x 3N; they
// are overwritten, never resized. Springs (stiffness and damping, forces.h SpringJacobianBlocks)
// and the ground penalty with its regularised friction contribute; gravity is constant.
void ForceJacobians(const CreatureModel& model, const double* rest_length, ParticleView p,
                    Eigen::MatrixXd& df_dx, Eigen::MatrixXd& df_dv);

}  // namespace hexgait
