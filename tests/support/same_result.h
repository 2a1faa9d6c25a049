// Bit-for-bit comparison of two runs' results, for tests of paths that must agree exactly
// (scalar and batched, one thread and several, a long run and its start).
#pragma once

#include <gtest/gtest.h>

#include <cstring>

#include "sim/step_loop.h"

namespace hexgait::test {

inline bool SameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline void ExpectSameResult(const RunResult& a, const RunResult& b, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_TRUE(SameBits(a.distance, b.distance)) << a.distance << " vs " << b.distance;
  EXPECT_EQ(a.fell, b.fell);
  EXPECT_TRUE(SameBits(a.fall_time, b.fall_time));
  EXPECT_EQ(a.fall_cycle, b.fall_cycle);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_TRUE(SameBits(a.end_time, b.end_time));
  EXPECT_EQ(a.diverged, b.diverged);
  EXPECT_EQ(a.diverge_step, b.diverge_step);
  EXPECT_EQ(a.diverge_reason, b.diverge_reason);
  EXPECT_TRUE(SameBits(a.min_body_height, b.min_body_height));
  EXPECT_TRUE(SameBits(a.max_tilt_degrees, b.max_tilt_degrees));
  EXPECT_TRUE(SameBits(a.mean_feet_on_ground, b.mean_feet_on_ground));
  EXPECT_EQ(a.feet_samples, b.feet_samples);
  EXPECT_EQ(a.stopped_early, b.stopped_early);
  EXPECT_EQ(a.foot_down_checks, b.foot_down_checks);
}

}  // namespace hexgait::test
