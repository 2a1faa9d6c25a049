// The mutable simulation state: particle positions and velocities (structure of arrays), the
// springs' current rest lengths (the controller writes them) and scratch space for forces.
// Everything is sized once when the state is made; the step loop never allocates.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/creature.h"
#include "sim/forces.h"

namespace hexgait {

struct SimState {
  std::vector<double> x, y, z;                          // positions
  std::vector<double> vx, vy, vz;                       // velocities
  std::vector<double> rest_length;                      // current rest length of every spring
  std::vector<double> fx, fy, fz;                       // force scratch, valid after ComputeForces
  std::vector<double> spring_fx, spring_fy, spring_fz;  // per-spring force scratch
  long long step = 0;
  double time = 0;

  int num_particles() const { return static_cast<int>(x.size()); }
  ForceView force_view() {
    return {fx.data(), fy.data(), fz.data(), spring_fx.data(), spring_fy.data(), spring_fz.data()};
  }
  ParticleView particle_view() const {
    return {x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data()};
  }
  Eigen::Vector3d position(int i) const { return {x[i], y[i], z[i]}; }
  Eigen::Vector3d velocity(int i) const { return {vx[i], vy[i], vz[i]}; }
};

// The creature standing still in its rest pose, every spring at its rest length.
SimState MakeRestState(const CreatureModel& model);

// Mean position of the body (non-foot) particles.
Eigen::Vector3d BodyCentre(const CreatureModel& model, const SimState& state);
// Lowest body particle height.
double LowestBodyHeight(const CreatureModel& model, const SimState& state);
// Angle in degrees between the body's up axis (from its front/rear and left/right particles)
// and the world's up axis.
double BodyTiltDegrees(const CreatureModel& model, const SimState& state);
// The same angle from the z component of the body's up axis (BodyAxes).
double TiltDegrees(double up_z);
// The tilt split in two, for plots: pitch is the forward axis's angle above the horizontal
// (nose up positive, -90..90); roll turns the left axis about the forward one (left side up
// positive, -180..180, so a creature on its back reads 180, not 0 like pitch would).
void BodyPitchRollDegrees(const CreatureModel& model, const SimState& state, double* pitch,
                          double* roll);
// Body up, forward and left axes (unit vectors) from the current particle positions.
void BodyAxes(const CreatureModel& model, const SimState& state, Eigen::Vector3d* forward,
              Eigen::Vector3d* left, Eigen::Vector3d* up);

// Kinetic + gravitational + spring + ground-penalty energy.
double TotalEnergy(const CreatureModel& model, const SimState& state);
double KineticEnergy(const CreatureModel& model, const SimState& state);

// Adds `impulse_y` of momentum along +y to the body particles, shared in proportion to their
// mass: each body particle's y velocity grows by impulse_y / (the body's mass). A push.
void PushBody(const CreatureModel& model, double impulse_y, SimState& state);

}  // namespace hexgait
