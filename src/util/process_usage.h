// What a process has used, read from a `rusage` (getrusage for this process, wait4 for a child
// that has ended): each figure converted in one place.
#pragma once

#include <sys/resource.h>

namespace hexgait {

// CPU seconds, user and system, every thread's.
inline double CpuSeconds(const rusage& usage) {
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Peak resident memory in MiB (Linux reports ru_maxrss in KiB).
inline double PeakResidentMiB(const rusage& usage) {
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

inline rusage ThisProcessUsage() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage;
}

// CPU seconds this process has used so far: over a stretch of wall time on T threads, the
// difference of two readings / (T x wall) is how busy they were.
inline double ProcessCpuSeconds() {
  return CpuSeconds(ThisProcessUsage());
}

// This process's peak resident memory so far, in MiB.
inline double PeakMemoryMiB() {
  return PeakResidentMiB(ThisProcessUsage());
}

}  // namespace hexgait
