// Integrators: each advances a SimState by one step of size dt, with the same signature, so
// the run loop is instantiated once per integrator and never branches on it per step.
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

enum class IntegratorKind { kEuler };

// Names as used on the command line ("euler"); ParseIntegrator throws InputError.
std::string IntegratorName(IntegratorKind kind);
IntegratorKind ParseIntegrator(const std::string& name);
std::vector<std::string> IntegratorNames();

// Explicit (forward) Euler, the paper's: position and velocity both from the old state.
struct EulerStepper {
  static void Step(const CreatureModel& model, SimState& state, double dt);
};

}  // namespace hexgait
