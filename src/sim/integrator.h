// Integrators: each advances a SimState by one step of size dt, with the same interface, so
// the run loop is instantiated once per integrator and never branches on it per step.
//
// The interface every stepper has (see RunLoop in run.h):
//   explicit Stepper(const CreatureModel& model);  // sizes its scratch space, once
//   void Begin(const CreatureModel& model, SimState& state);  // once, before the first step
//   void Step(const CreatureModel& model, SimState& state, double dt);  // never allocates
// When Step(k) runs, state.rest_length holds the controller's rest lengths for the END of the
// step, L(t_k + dt) (motor/rest_schedule.h); steppers that need L at the start of the step or
// in between keep a copy of the previous step's lengths and interpolate linearly, which is
// exact because the lengths are piecewise linear with kinks on the step grid.
//
// The other integrators live in sim/integrators/, one per file.
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

enum class IntegratorKind { kEuler, kSymplecticEuler, kVerlet, kRk4, kImplicitEuler };

// Names as used on the command line ("euler"); ParseIntegrator throws InputError.
std::string IntegratorName(IntegratorKind kind);
IntegratorKind ParseIntegrator(const std::string& name);
std::vector<std::string> IntegratorNames();
std::vector<IntegratorKind> AllIntegrators();
// Force evaluations per step (for the benchmarks' cost accounting).
int ForceEvaluationsPerStep(IntegratorKind kind);

// Explicit (forward) Euler, the paper's: position and velocity both from the old state. Uses
// the end-of-step rest lengths as it always has (a lag of one step in the motor's command,
// first order like the method itself), so the paper's results stay bit-identical.
struct EulerStepper {
  EulerStepper() = default;
  explicit EulerStepper(const CreatureModel&) {}
  void Begin(const CreatureModel&, SimState&) {}
  static void Step(const CreatureModel& model, SimState& state, double dt);
};

}  // namespace hexgait
