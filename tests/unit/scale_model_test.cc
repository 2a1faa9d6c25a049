// The cluster model behind `hexgait bench scale` and docs/scaling.md, on numbers worked by hand.
#include "bench/scale_model.h"

#include <gtest/gtest.h>

namespace hexgait {
namespace {

// 4 cores x 2 lanes per rank, 1 s per evaluation per core, nothing else.
ClusterModel ComputeOnly() {
  ClusterModel m;
  m.cores_per_rank = 4;
  m.lanes = 2;
  m.seconds_per_eval = 1;
  m.serial_seconds_per_eval = 0;
  m.bytes_per_eval = 0;
  m.latency_seconds = 0;
  return m;
}

TEST(ScaleModel, FullRoundsScalePerfectly) {
  // 64 creatures on 4 ranks: 16 each, 2 full rounds of 8 slots, 2 lanes x 1 s each.
  const GenerationTime t = PredictGeneration(ComputeOnly(), 64, 4);
  EXPECT_DOUBLE_EQ(t.seconds_compute, 4.0);
  EXPECT_DOUBLE_EQ(t.seconds_communication, 0.0);
  EXPECT_DOUBLE_EQ(t.efficiency, 1.0);
}

TEST(ScaleModel, AnUnfilledRoundCostsAFullOne) {
  // 12 creatures on 4 ranks: 3 each, one round that costs as much as 8 would.
  const GenerationTime t = PredictGeneration(ComputeOnly(), 12, 4);
  EXPECT_DOUBLE_EQ(t.seconds_compute, 2.0);
  // One rank runs 12 in 2 rounds (4 s); four ranks take 2 s each: 4 / (4 x 2).
  EXPECT_DOUBLE_EQ(t.efficiency, 0.5);
}

TEST(ScaleModel, MoreRanksThanCreaturesIdle) {
  const GenerationTime t = PredictGeneration(ComputeOnly(), 2, 8);
  EXPECT_DOUBLE_EQ(t.seconds_compute, 2.0);
  EXPECT_DOUBLE_EQ(t.efficiency, 2.0 / (8 * 2.0));
}

TEST(ScaleModel, CommunicationGoesThroughRankZero) {
  ClusterModel m = ComputeOnly();
  m.latency_seconds = 1e-3;
  m.bytes_per_eval = 1000;
  m.bytes_per_second = 1e6;
  // 3 other ranks x 3 messages x 1 ms, and 3/4 of 64 creatures' bytes at 1 MB/s.
  const GenerationTime t = PredictGeneration(m, 64, 4);
  EXPECT_NEAR(t.seconds_communication, 9e-3 + 48 * 1000 / 1e6, 1e-12);
  EXPECT_DOUBLE_EQ(PredictGeneration(m, 64, 1).seconds_communication, 0.0);
  EXPECT_LT(t.efficiency, 1.0);
}

TEST(ScaleModel, SerialWorkIsAmdahlsLimit) {
  ClusterModel m = ComputeOnly();
  m.serial_seconds_per_eval = 0.25;  // as long as a full slot's compute share
  const long long population = 1 << 16;
  // Compute shrinks with ranks, the serial part does not: efficiency falls towards 0.
  const double e64 = PredictGeneration(m, population, 64).efficiency;
  const double e1024 = PredictGeneration(m, population, 1024).efficiency;
  EXPECT_GT(e64, e1024);
  EXPECT_LT(e1024, 0.1);
  const GenerationTime one = PredictGeneration(m, population, 1);
  EXPECT_DOUBLE_EQ(one.efficiency, 1.0);
  EXPECT_DOUBLE_EQ(one.seconds_serial, population * 0.25);
}

}  // namespace
}  // namespace hexgait
