// The step loop, for one creature (the run layer in src/run/ is the requests above it): step,
// let the controller change rest lengths when an instruction is due, hand the state to an
// observer, and watch for a fall or divergence every few steps.
//
// The observer is a template parameter: the GA passes NullObserver, whose empty OnStep inlines
// away, and a movie writer passes one that renders only when a frame is due.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "model/creature.h"
#include "motor/controller.h"
#include "sim/integrator.h"
#include "sim/state.h"
#include "sim/steppers.h"

namespace hexgait {

inline constexpr double kPaperTimeStep = 0.0025;
inline constexpr double kPaperDuration = 1000.0;

// The check interval (RunOptions::check_interval) for a step of `dt`: the whole number of steps
// closest to 0.1 time units, at least 1 (40 at the paper's step). Tied to time rather than steps,
// so a fall is found to within a tenth of a time unit (the precision `simulate` prints) and the
// feet are sampled for duty factors at the same times whatever the step; a gait cycle lasts 66
// time units, so a tenth resolves it finely without testing every step.
int CheckIntervalFor(double dt);

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
  // program, so it rarely fires (docs/speed.md, measured by `hexgait bench early-stop`).
  bool early_stop = false;
  double rest_kinetic_energy = 1e-4;
  // End the run at the fall, with stopped_early set: for questions about when a gait falls,
  // not how far it gets (`hexgait endurance`). Off by default.
  bool stop_at_fall = false;
  // A sideways push: at push_time, an impulse of push_impulse (mass x length / time) along +y,
  // the creature's left, shared by the body particles in proportion to their mass (each gains
  // push_impulse / body mass of y velocity). 0: none, the default. Scalar path only; it is
  // applied between two stretches of the run, never tested inside the step loop.
  double push_time = 0;
  double push_impulse = 0;
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
  // Per leg (the model's order), the checks among those feet_samples at which its foot touched
  // the ground: over feet_samples, the leg's duty factor, the fraction of the walk it stands
  // (DutyFactor). Legs past the model's stay 0.
  std::array<long long, kMaxLegs> foot_down_checks{};
  double DutyFactor(int leg) const {
    return feet_samples > 0 ? static_cast<double>(foot_down_checks[leg]) / feet_samples : 0.0;
  }
  bool stopped_early = false;  // early_stop or stop_at_fall ended the run at end_time
};

struct NullObserver {
  void OnStep(const SimState&) {}
};

// The divergence test, on a double or on a vector of doubles (many lanes at once,
// sim/lane_measures.cc), over any number of particles: every position and squared speed
// finite, and every speed within `limit`. Add the particles, then ask (per lane).
template <class V>
class BoundsTest {
 public:
  explicit BoundsTest(double limit) : limit2_(limit * limit) {}
  [[gnu::always_inline]] void Add(V x, V y, V z, V vx, V vy, V vz) {
    const V speed2 = vx * vx + vy * vy + vz * vz;
    // v - v is 0 exactly for a finite v and NaN otherwise, and a NaN survives every sum.
    not_finite_ = not_finite_ + (x - x) + (y - y) + (z - z) + (speed2 - speed2);
    fastest2_ = speed2 > fastest2_ ? speed2 : fastest2_;
  }
  [[gnu::always_inline]] auto Finite() const { return not_finite_ == 0; }
  [[gnu::always_inline]] auto Passes() const { return (not_finite_ == 0) & (fastest2_ <= limit2_); }

 private:
  double limit2_;
  V not_finite_ = V(), fastest2_ = V();
};

// What the fall check reads from a state besides the divergence test.
struct BodyMeasures {
  double lowest = 0;  // LowestBodyHeight
  double up_z = 0;    // the z component of the body's up axis (BodyAxes)
  uint32_t feet = 0;  // FeetOnGround
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
  // Returns false when the run must stop (diverged, at rest with early_stop, or fallen with
  // stop_at_fall).
  bool Check(const SimState& state);
  // The same check of a state at `time` measured elsewhere (sim/lane_measures.h measures a
  // batch's lanes at once), for a state known to pass the divergence test and a run without
  // early_stop (whose rest test needs the whole state): the same result, bit for bit.
  bool CheckMeasured(const BodyMeasures& body, double time);

 private:
  // Check after its divergence test; `state` is read only for early_stop's rest test.
  bool Record(const BodyMeasures& body, double time, const SimState* state);

  const CreatureModel& model_;
  double cycle_period_;
  const RunOptions& options_;
  RunResult& result_;
  int still_checks_ = 0;  // consecutive checks at rest after the fall (early_stop)
};

// A run that can be continued: it keeps the stepper (Verlet and RK4 carry data from one step
// to the next), the fall monitor and the count to its next check, so advancing it in chunks (a
// movie advances each creature one frame at a time) gives the same bits as one call of
// Simulate over the whole duration. Not movable: the monitor refers to the members.
template <class Stepper>
class SteppedRun {
 public:
  SteppedRun(const CreatureModel& model, MotorController& controller, SimState& state,
             const RunOptions& options)
      : model_(model),
        controller_(controller),
        state_(state),
        options_(options),
        total_(std::llround(options.duration / options.dt)),
        start_x_(BodyCentre(model, state).x()),
        monitor_(model, controller, options_, result_),
        stepper_(model),
        until_check_(options.check_interval) {
    result_.min_body_height = INFINITY;
    stepper_.Begin(model, state);
  }
  SteppedRun(const SteppedRun&) = delete;
  SteppedRun& operator=(const SteppedRun&) = delete;

  // Advances by up to `steps` steps, handing every state to `observer`. Returns false once the
  // run has ended: all its steps done, diverged, or stopped early (RunOptions::early_stop).
  template <class Observer>
  bool Advance(long long steps, Observer& observer) {
    const long long end = std::min(done_ + steps, total_);
    int until_check = until_check_;  // a local, so the hot loop keeps it in a register
    for (; !ended_ && done_ < end; ++done_) {
      controller_.Update(state_.step, state_.rest_length.data());
      stepper_.Step(model_, state_, options_.dt);
      state_.time = static_cast<double>(state_.step) * options_.dt;
      observer.OnStep(state_);
      if (--until_check == 0) {
        until_check = options_.check_interval;
        ended_ = !monitor_.Check(state_);
      }
    }
    until_check_ = until_check;
    return !ended_ && done_ < total_;
  }

  // What the run has found so far: fall, divergence, lowest body and largest tilt (the
  // distance is filled in by Finish).
  const RunResult& result_so_far() const { return result_; }
  long long steps_left() const { return total_ - done_; }

  // The last check, then the result as Simulate returns it. Call once, after the last Advance.
  RunResult Finish() {
    if (!result_.diverged) monitor_.Check(state_);
    result_.steps = state_.step;
    result_.end_time = state_.time;
    result_.distance = result_.diverged ? 0.0 : BodyCentre(model_, state_).x() - start_x_;
    return result_;
  }

 private:
  const CreatureModel& model_;
  MotorController& controller_;
  SimState& state_;
  const RunOptions options_;
  const long long total_;
  const double start_x_;
  RunResult result_;
  RunMonitor monitor_;
  Stepper stepper_;
  int until_check_;
  long long done_ = 0;
  bool ended_ = false;
};

template <class Stepper, class Observer>
RunResult RunLoop(const CreatureModel& model, MotorController& controller, SimState& state,
                  const RunOptions& options, Observer& observer) {
  SteppedRun<Stepper> run(model, controller, state, options);
  run.Advance(run.steps_left(), observer);
  return run.Finish();
}

// Runs `options.duration` time units from `state`, with the integrator `options` names.
template <class Observer>
RunResult Simulate(const CreatureModel& model, MotorController& controller, SimState& state,
                   const RunOptions& options, Observer& observer) {
  return WithStepperType(options.integrator, [&]<class Stepper>() {
    return RunLoop<Stepper>(model, controller, state, options, observer);
  });
}

// Simulate, advanced `chunk` steps at a time with `on_chunk(steps_done, steps_total)` called
// between chunks (for a progress bar): the same bits as one call of Simulate, and nothing added
// to the step loop.
template <class Observer, class OnChunk>
RunResult SimulateInChunks(const CreatureModel& model, MotorController& controller, SimState& state,
                           const RunOptions& options, Observer& observer, long long chunk,
                           OnChunk&& on_chunk) {
  return WithStepperType(options.integrator, [&]<class Stepper>() {
    SteppedRun<Stepper> run(model, controller, state, options);
    const long long total = run.steps_left();
    while (run.Advance(chunk, observer)) on_chunk(total - run.steps_left(), total);
    return run.Finish();
  });
}

// A SteppedRun whose integrator is chosen at run time, for callers that advance a run in
// chunks with no observer (a movie: one virtual call per frame, none per step).
class ResumableRun {
 public:
  virtual ~ResumableRun() = default;
  virtual bool Advance(long long steps) = 0;
  virtual const RunResult& result_so_far() const = 0;
  virtual RunResult Finish() = 0;
};

// Starts a run of `options.integrator`; `controller` and `state` must outlive it.
std::unique_ptr<ResumableRun> StartRun(const CreatureModel& model, MotorController& controller,
                                       SimState& state, const RunOptions& options);

}  // namespace hexgait
