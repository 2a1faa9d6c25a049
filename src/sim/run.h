// The simulation loop: step, let the controller change rest lengths when an instruction is due,
// hand the state to an observer, and watch for a fall or divergence every few steps.
//
// The observer is a template parameter: the GA passes NullObserver, whose empty OnStep inlines
// away, and a movie writer passes one that renders only when a frame is due.
#pragma once

#include <cmath>
#include <string>

#include "model/creature.h"
#include "motor/controller.h"
#include "sim/integrator.h"
#include "sim/state.h"
#include "sim/steppers.h"

namespace hexgait {

inline constexpr double kPaperTimeStep = 0.0025;
inline constexpr double kPaperDuration = 1000.0;

struct RunOptions {
  double dt = kPaperTimeStep;
  double duration = kPaperDuration;
  IntegratorKind integrator = IntegratorKind::kEuler;
  // Fall and divergence checks run every this many steps (0.1 time units at the paper's step).
  int check_interval = 40;
  // A particle faster than this (length per time unit) means the integration has blown up: the
  // energy blow-up criterion (a particle's kinetic energy ~10^8 times a walking creature's).
  double divergence_speed = 1e3;
  // Stop a run once the creature has fallen and come to rest: kinetic energy below
  // rest_kinetic_energy at every check for a whole gait cycle. Off by default, so the paper's
  // numbers are untouched; in this model a fallen creature keeps crawling under its motor
  // program, so it rarely fires (README.md, "Speed", measured by `hexgait bench early-stop`).
  bool early_stop = false;
  double rest_kinetic_energy = 1e-4;
};

struct RunResult {
  double distance = 0;  // body centre's x displacement, start to end
  bool fell = false;
  double fall_time = 0;
  int fall_cycle = 0;  // 1-based gait cycle of the fall, 0 if it did not fall
  long long steps = 0;
  double end_time = 0;
  bool diverged = false;
  double diverge_time = 0;
  long long diverge_step = 0;
  std::string diverge_reason;
  double min_body_height = 0;
  double max_tilt_degrees = 0;
  // Mean number of feet touching the ground before the fall (or over the run), sampled at
  // every check: about 5 for a careful walker, 2 for a hopping one.
  double mean_feet_on_ground = 0;
  long long feet_samples = 0;
  bool stopped_early = false;  // RunOptions::early_stop ended the run at end_time
};

struct NullObserver {
  void OnStep(const SimState&) {}
};

// Checked every check_interval steps: fall (body too low or tilted) and divergence.
class RunMonitor {
 public:
  RunMonitor(const CreatureModel& model, const MotorController& controller,
             const RunOptions& options, RunResult& result)
      : RunMonitor(model, controller.cycle_period(), options, result) {}
  // `cycle_period` dates a fall by gait cycle (the batched simulator has no MotorController).
  RunMonitor(const CreatureModel& model, double cycle_period, const RunOptions& options,
             RunResult& result)
      : model_(model), cycle_period_(cycle_period), options_(options), result_(result) {}
  // Returns false when the run must stop (diverged, or at rest with early_stop).
  bool Check(const SimState& state);

 private:
  const CreatureModel& model_;
  double cycle_period_;
  const RunOptions& options_;
  RunResult& result_;
  int still_checks_ = 0;  // consecutive checks at rest after the fall (early_stop)
};

template <class Stepper, class Observer>
RunResult RunLoop(const CreatureModel& model, MotorController& controller, SimState& state,
                  const RunOptions& options, Observer& observer) {
  RunResult result;
  result.min_body_height = INFINITY;
  const double start_x = BodyCentre(model, state).x();
  const long long total = static_cast<long long>(std::llround(options.duration / options.dt));
  RunMonitor monitor(model, controller, options, result);
  Stepper stepper(model);
  stepper.Begin(model, state);
  int until_check = options.check_interval;
  // The controller follows the state's own step count, so a run can be continued in chunks
  // (a movie advances each creature one frame at a time) with the same result.
  for (long long k = 0; k < total; ++k) {
    controller.Update(state.step, state.rest_length.data());
    stepper.Step(model, state, options.dt);
    state.time = static_cast<double>(state.step) * options.dt;
    observer.OnStep(state);
    if (--until_check == 0) {
      until_check = options.check_interval;
      if (!monitor.Check(state)) break;
    }
  }
  if (!result.diverged) monitor.Check(state);
  result.steps = state.step;
  result.end_time = state.time;
  result.distance = result.diverged ? 0.0 : BodyCentre(model, state).x() - start_x;
  return result;
}

// Runs `options.duration` time units from `state`, with the integrator `options` names.
template <class Observer>
RunResult Simulate(const CreatureModel& model, MotorController& controller, SimState& state,
                   const RunOptions& options, Observer& observer) {
  switch (options.integrator) {
    case IntegratorKind::kEuler:
      return RunLoop<EulerStepper>(model, controller, state, options, observer);
    case IntegratorKind::kSymplecticEuler:
      return RunLoop<SymplecticEulerStepper>(model, controller, state, options, observer);
    case IntegratorKind::kVerlet:
      return RunLoop<VerletStepper>(model, controller, state, options, observer);
    case IntegratorKind::kRk4:
      return RunLoop<Rk4Stepper>(model, controller, state, options, observer);
    case IntegratorKind::kImplicitEuler:
      return RunLoop<ImplicitEulerStepper>(model, controller, state, options, observer);
  }
  return {};
}

}  // namespace hexgait
