#include "run/work_size.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace hexgait {

double CreatureStepCost(const CreatureModel& model) {
  const double size = model.num_particles() + static_cast<double>(model.num_springs());
  return std::max(1.0, size / (14.0 + 40.0));
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
