#include "sim/evaluate.h"

#include <cmath>
#include <stdexcept>

#include "motor/leg_targets.h"
#include "sim/trace.h"

namespace hexgait {

bool RunMonitor::Check(const SimState& state) {
  const int n = state.num_particles();
  for (int i = 0; i < n; ++i) {
    BoundsTest<double> particle(options_.divergence_speed);
    particle.Add(state.x[i], state.y[i], state.z[i], state.vx[i], state.vy[i], state.vz[i]);
    if (!particle.Passes()) {
      const bool finite = particle.Finite();
      result_.diverged = true;
      result_.diverge_time = state.time;
      result_.diverge_step = state.step;
      result_.diverge_reason =
          !finite ? "non-finite state of particle '" + model_.particle_names[i] + "'"
                  : "particle '" + model_.particle_names[i] + "' faster than the divergence limit";
      return false;
    }
  }
  Eigen::Vector3d up;
  BodyAxes(model_, state, nullptr, nullptr, &up);
  return Record({LowestBodyHeight(model_, state), up.z(), FeetOnGround(model_, state)}, state.time,
                &state);
}

bool RunMonitor::CheckMeasured(const BodyMeasures& body, double time) {
  if (options_.early_stop) throw std::logic_error("early_stop needs the whole state");
  return Record(body, time, nullptr);
}

bool RunMonitor::Record(const BodyMeasures& body, double time, const SimState* state) {
  const double lowest = body.lowest;
  const double tilt = TiltDegrees(body.up_z);
  if (!result_.fell) {
    const uint32_t down = body.feet;
    int feet = 0;
    for (size_t leg = 0; leg < model_.legs.size(); ++leg) {
      feet += down >> leg & 1u;
      result_.foot_down_checks[leg] += down >> leg & 1u;
    }
    ++result_.feet_samples;
    result_.mean_feet_on_ground += (feet - result_.mean_feet_on_ground) / result_.feet_samples;
  }
  result_.min_body_height = std::fmin(result_.min_body_height, lowest);
  result_.max_tilt_degrees = std::fmax(result_.max_tilt_degrees, tilt);
  if (!result_.fell &&
      (lowest < model_.physics.fall_height || tilt > model_.physics.fall_tilt_degrees)) {
    result_.fell = true;
    result_.fall_time = time;
    result_.fall_cycle = static_cast<int>(std::floor(time / cycle_period_)) + 1;
  }
  if (options_.stop_at_fall && result_.fell) {
    result_.stopped_early = true;
    return false;
  }
  if (options_.early_stop && result_.fell) {
    // At rest for a whole gait cycle: the periodic motor program has had every chance to move
    // it and did not, so the rest of the run cannot add to the distance.
    still_checks_ =
        KineticEnergy(model_, *state) < options_.rest_kinetic_energy ? still_checks_ + 1 : 0;
    if (still_checks_ * options_.check_interval * options_.dt >= cycle_period_) {
      result_.stopped_early = true;
      return false;
    }
  }
  return true;
}

RunResult EvaluateRestLengths(const CreatureModel& model, const MotorProgram& program,
                              const RestLengthTable& table, const RunOptions& options) {
  MotorController controller(model, program, table, options.dt);
  SimState state = MakeRestState(model);
  NullObserver observer;
  if (options.push_impulse == 0) return Simulate(model, controller, state, options, observer);
  // The run up to the push, the push, the rest: the same steps and checks as one run.
  return WithStepperType(options.integrator, [&]<class Stepper>() {
    SteppedRun<Stepper> run(model, controller, state, options);
    if (run.Advance(std::llround(options.push_time / options.dt), observer)) {
      PushBody(model, options.push_impulse, state);
      run.Advance(run.steps_left(), observer);
    }
    return run.Finish();
  });
}

double LargestStableStep(const CreatureModel& model, const MotorProgram& program,
                         const RestLengthTable& table, RunOptions options, int max_halvings) {
  for (int i = 0; i < max_halvings; ++i) {
    options.dt *= 0.5;
    if (!EvaluateRestLengths(model, program, table, options).diverged) return options.dt;
  }
  return 0;
}

}  // namespace hexgait
