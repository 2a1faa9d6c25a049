// The comparison point for `hexgait bench speed`: the same physics written the plain way, an
// array of Eigen 3-vectors per quantity and a loop over springs with Eigen expressions. It is
// what a first implementation looks like; the scalar SoA path (sim/forces.cc) and the batched
// kernel (sim/batch_kernel_impl.h) are measured against it. Not used by the simulator.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/creature.h"

namespace hexgait {

struct NaiveState {
  std::vector<Eigen::Vector3d> position, velocity, force;
};

NaiveState MakeNaiveState(const CreatureModel& model);

// One explicit Euler step: spring, gravity and ground forces, then positions and velocities
// from the old state. `rest_length` holds the springs' current rest lengths.
void NaiveEulerStep(const CreatureModel& model, const double* rest_length, NaiveState& state,
                    double dt);

}  // namespace hexgait
