// Runs code with a stepper chosen at run time: WithStepper(kind, model, fn) builds the stepper
// `kind` names and calls fn(stepper) once, so fn's loop is compiled once per integrator and
// never branches on the kind per step (the free-flight benches and tests use it; Simulate and
// StartRun in run.h dispatch through WithStepperType).
#pragma once

#include "model/creature.h"
#include "sim/integrator.h"
#include "sim/integrators/implicit_euler.h"
#include "sim/integrators/rk4.h"
#include "sim/integrators/symplectic_euler.h"
#include "sim/integrators/verlet.h"

namespace hexgait {

// Calls fn.template operator()<Stepper>() for the stepper type `kind` names and returns its
// result: the one place that maps an IntegratorKind to a type, so a new integrator is one new
// file plus one case here.
template <class Fn>
decltype(auto) WithStepperType(IntegratorKind kind, Fn&& fn) {
  switch (kind) {
    case IntegratorKind::kEuler:
      return fn.template operator()<EulerStepper>();
    case IntegratorKind::kSymplecticEuler:
      return fn.template operator()<SymplecticEulerStepper>();
    case IntegratorKind::kVerlet:
      return fn.template operator()<VerletStepper>();
    case IntegratorKind::kRk4:
      return fn.template operator()<Rk4Stepper>();
    case IntegratorKind::kImplicitEuler:
      return fn.template operator()<ImplicitEulerStepper>();
  }
  return fn.template operator()<EulerStepper>();  // unreachable: every kind is listed above
}

template <class Fn>
void WithStepper(IntegratorKind kind, const CreatureModel& model, Fn&& fn) {
  WithStepperType(kind, [&]<class Stepper>() {
    Stepper stepper(model);
    fn(stepper);
  });
}

}  // namespace hexgait
