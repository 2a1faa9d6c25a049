#include "run/work_size.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace hexgait {

namespace {

// A creature-step on one core of the machine the model was calibrated on (AMD EPYC, Zen 5;
// scripts/step_cost.sh, median of three): the hexapod (14 particles, 40 springs) takes 344 ns
// alone (simulate) and 44 ns in a batch (evolve's population of 16, double). Taken about 2x
// faster, so an estimate stays within a factor of two of that machine and a machine twice as
// fast is not refused a run it would finish within the hour. A float batch (about 22 ns,
// `hexgait bench speed`) is estimated about 10% slow: only a float run of 55 to 60 minutes is
// refused that would have finished within the hour.
constexpr double kSecondsPerStep = 1.8e-7;
constexpr double kSecondsPerBatchedStep = 2.4e-8;

// Past the hexapod a step costs more per particle and spring than a linear model says: a batch
// of large creatures (or one very large creature) no longer fits the core's caches. The cost
// grows by 1/knee per element; the knees are fitted on scripts/step_cost.sh's creatures up to
// 1,000 particles and 5,956 springs (its table is in docs/reliability.md): every row's estimate
// lies between half its measured time and its measured time
// (WorkSize.TheEstimateIsWithinAFactorOfTwoOfMeasuredSteps).
constexpr double kHexapodSize = 14.0 + 40.0;
constexpr double kScalarKnee = 20000;
constexpr double kBatchedKnee = 6000;

// A creature-step of `model` against the hexapod's; never below 1.
double CreatureStepCost(const CreatureModel& model, StepPath path) {
  const double size = model.num_particles() + static_cast<double>(model.num_springs());
  const double knee = path == StepPath::kScalar ? kScalarKnee : kBatchedKnee;
  return std::max(1.0, size / kHexapodSize * (1 + (size - kHexapodSize) / knee));
}

}  // namespace

double EstimatedSimulationSeconds(const CreatureModel& model, double runs, double steps,
                                  StepPath path, double workers) {
  const double per_step = path == StepPath::kScalar ? kSecondsPerStep : kSecondsPerBatchedStep;
  return runs * steps * per_step * CreatureStepCost(model, path) / std::max(1.0, workers);
}

std::string DurationText(double seconds) {
  struct Unit {
    const char* name;
    double seconds;
  };
  static constexpr Unit kUnits[] = {
      {"years", 365.25 * 86400}, {"days", 86400}, {"hours", 3600}, {"minutes", 60}};
  char text[64];
  for (const Unit& unit : kUnits) {
    if (seconds >= 2 * unit.seconds) {
      std::snprintf(text, sizeof text, "%.3g %s", seconds / unit.seconds, unit.name);
      return text;
    }
  }
  std::snprintf(text, sizeof text, "%.3g seconds", seconds);
  return text;
}

void RefuseLongRun(const std::string& what, double seconds, bool allow_long) {
  if (allow_long || !(seconds > kLongRunSeconds)) return;
  throw InputError(what + ": at least " + DurationText(seconds) +
                   " of computing (more than an hour); pass --allow-long to run it anyway");
}

void RefuseLongEvaluations(const std::string& what, const CreatureModel& model, double evaluations,
                           const RunOptions& run, double workers, bool allow_long) {
  const double steps = run.duration / run.dt;
  char text[160];
  std::snprintf(text, sizeof text, " are %.3g evaluations of %.3g steps on %.0f threads",
                evaluations, steps, workers);
  RefuseLongRun(what + text,
                EstimatedSimulationSeconds(model, evaluations, steps, StepPath::kBatched, workers),
                allow_long);
}

void RefuseLongMovie(const std::string& what, long long frames, bool allow_long) {
  if (allow_long || frames <= kMaxMovieFrames) return;
  throw InputError(what + ": " + std::to_string(frames) + " frames, more than " +
                   std::to_string(kMaxMovieFrames) + "; pass --allow-long to make it anyway");
}

std::string StepsText(double time, double dt, const std::string& time_flag) {
  char text[128];
  std::snprintf(text, sizeof text, "%s %g at --dt %g is %.3g steps", time_flag.c_str(), time, dt,
                std::round(time / dt));
  return text;
}

}  // namespace hexgait
