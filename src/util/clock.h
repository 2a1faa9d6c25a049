// The one clock for the wall times hexgait reports (generations, movies, benchmarks, records):
// steady, so a change of the system time never makes a duration negative.
#pragma once

#include <chrono>

namespace hexgait {

using Clock = std::chrono::steady_clock;

// Seconds from `start` to now.
inline double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Seconds from `start` to `end`.
inline double SecondsBetween(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

}  // namespace hexgait
