// The right-hand side of the 6N first-order ODEs: forces from springs (Hooke plus damping
// along the spring), gravity, and penalty ground contact with regularised Coulomb friction.
#pragma once

#include <Eigen/Core>

#include "model/creature.h"

namespace hexgait {

// Views of a state's arrays, so integrators with stage states (RK4, ...) share one kernel.
struct ParticleView {
  const double *x, *y, *z, *vx, *vy, *vz;
};
struct ForceView {
  double *fx, *fy, *fz;                       // per particle (output)
  double *spring_fx, *spring_fy, *spring_fz;  // per spring (scratch)
};

// Writes the total force on every particle. `rest_length` holds the springs' current rest
// lengths. Ground forces are only computed for particles below the ground plane.
void ComputeForces(const CreatureModel& model, const double* rest_length, ParticleView p,
                   ForceView f);

}  // namespace hexgait

namespace hexgait {

// The 3x3 derivative of one spring's force on end b with respect to the position of end b,
// d f_b / d x_b, for a spring from a to b (d f_b / d x_a is its negative). Used by implicit
// integrators and checked against finite differences in the tests. Damping is not included.
Eigen::Matrix3d SpringStiffnessBlock(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     double stiffness, double rest_length);
// Both derivatives of the force on end b of a spring from a to b, damping included:
// d f_b / d x_b (stiffness and the change of the damping direction) and d f_b / d v_b. The
// derivatives with respect to end a are their negatives. Used by the implicit integrator and
// checked against finite differences of SpringForceOnB in the tests.
void SpringJacobianBlocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& va, const Eigen::Vector3d& vb, double stiffness,
                          double damping, double rest_length, Eigen::Matrix3d* df_dx,
                          Eigen::Matrix3d* df_dv);
// The force on end b of that spring, including damping along the spring.
Eigen::Vector3d SpringForceOnB(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& va, const Eigen::Vector3d& vb,
                               double stiffness, double damping, double rest_length);

}  // namespace hexgait
