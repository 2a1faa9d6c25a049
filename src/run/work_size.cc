#include "run/work_size.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace hexgait {

namespace {

// The hexapod's creature-step, one core. Scalar: 260 to 300 ns measured (`hexgait bench speed`,
// rows "naive" and "single", docs/speed.md), taken 3x faster. Batched: 21.8 ns measured at 16
// float lanes (docs/speed.md), taken 2x faster.
constexpr double kSecondsPerStep = 1e-7;
constexpr double kSecondsPerBatchedStep = 1e-8;

// A creature-step of `model` against the hexapod's (14 particles, 40 springs), on which the
// constants above were measured; never below 1. scripts/step_cost.sh measures the real ratio:
// this model is about 2x low at 1,000 particles (not yet recalibrated).
double CreatureStepCost(const CreatureModel& model) {
  const double size = model.num_particles() + static_cast<double>(model.num_springs());
  return std::max(1.0, size / (14.0 + 40.0));
}

}  // namespace

double EstimatedSimulationSeconds(const CreatureModel& model, double runs, double steps,
                                  StepPath path, double workers) {
  const double per_step = path == StepPath::kScalar ? kSecondsPerStep : kSecondsPerBatchedStep;
  return runs * steps * per_step * CreatureStepCost(model) / std::max(1.0, workers);
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
