// Symplectic (semi-implicit) Euler: the velocity first, from the old forces, then the position
// with the NEW velocity. First order like explicit Euler, but for conservative forces it keeps
// the energy bounded instead of letting it grow (docs/model.md, "Integrators").
#pragma once

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

struct SymplecticEulerStepper {
  SymplecticEulerStepper() = default;
  explicit SymplecticEulerStepper(const CreatureModel&) {}
  void Begin(const CreatureModel&, SimState&) {}
  static void Step(const CreatureModel& model, SimState& state, double dt);
};

}  // namespace hexgait
