// The one clock for the wall times hexgait reports (generations, movies, benchmarks, records):
// steady, so a change of the system time never makes a duration negative.
#pragma once

#include <sys/resource.h>

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

// CPU seconds this process has used so far, user and system, every thread's: over a stretch of
// wall time on T threads, the difference of two readings / (T x wall) is how busy they were.
inline double ProcessCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace hexgait
