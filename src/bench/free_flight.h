// A contact-free test problem: the creature high above the ground with ground contact off,
// gravity on and its springs set vibrating (rest lengths changed by up to 5%, velocities
// disturbed). With damping off its total energy is exactly conserved by the true solution; the
// energy-drift bench and the convergence-order tests use it.
#pragma once

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

struct FreeFlight {
  CreatureModel model;
  SimState initial;
  double vibration_energy = 0;  // kinetic + spring energy at t = 0 (the drift's scale)
};

FreeFlight MakeFreeFlight(const CreatureModel& creature, bool spring_damping);

// Gravitational potential energy, so the drift can be measured against vibration energy.
double GravityEnergy(const CreatureModel& model, const SimState& state);

}  // namespace hexgait
