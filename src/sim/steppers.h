// Runs code with a stepper chosen at run time: WithStepper(kind, model, fn) builds the stepper
// `kind` names and calls fn(stepper) once, so fn's loop is compiled once per integrator and
// never branches on the kind per step (the free-flight benches and tests use it; RunLoop is
// dispatched by Simulate in run.h).
#pragma once

#include "model/creature.h"
#include "sim/integrator.h"
#include "sim/integrators/implicit_euler.h"
#include "sim/integrators/rk4.h"
#include "sim/integrators/symplectic_euler.h"
#include "sim/integrators/verlet.h"

namespace hexgait {

template <class Fn>
void WithStepper(IntegratorKind kind, const CreatureModel& model, Fn&& fn) {
  switch (kind) {
    case IntegratorKind::kEuler: {
      EulerStepper s(model);
      fn(s);
      return;
    }
    case IntegratorKind::kSymplecticEuler: {
      SymplecticEulerStepper s(model);
      fn(s);
      return;
    }
    case IntegratorKind::kVerlet: {
      VerletStepper s(model);
      fn(s);
      return;
    }
    case IntegratorKind::kRk4: {
      Rk4Stepper s(model);
      fn(s);
      return;
    }
    case IntegratorKind::kImplicitEuler: {
      ImplicitEulerStepper s(model);
      fn(s);
      return;
    }
  }
}

}  // namespace hexgait
