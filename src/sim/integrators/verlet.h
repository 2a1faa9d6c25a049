// Velocity Verlet (kick, drift, kick) with one force evaluation per step.
//
// The forces depend on velocity (spring damping, ground damping, friction), so the force at
// the new positions needs a velocity that velocity Verlet does not have yet. We evaluate it at
// the predicted velocity v_k + dt a_k (= half-step velocity + dt/2 a_k), which is O(dt^2) from
// v_{k+1}: the step stays second order (the half-step velocity alone, O(dt) off, would make
// damped motion first order), and for velocity-independent forces this is exactly velocity
// Verlet, symplectic and time-reversible. That force is reused as the next step's first kick.
#pragma once

#include <array>
#include <vector>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

class VerletStepper {
 public:
  explicit VerletStepper(const CreatureModel& model);
  // Forces at the initial state, for the first kick.
  void Begin(const CreatureModel& model, SimState& state);
  void Step(const CreatureModel& model, SimState& state, double dt);

 private:
  // By axis: the acceleration at the current state (from the last step) and the predicted
  // end-of-step velocity.
  std::array<std::vector<double>, 3> acceleration_, predicted_velocity_;
};

}  // namespace hexgait
