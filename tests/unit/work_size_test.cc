// The long-run estimate against measured step times (run/work_size.h).
#include "run/work_size.h"

#include <gtest/gtest.h>

#include "motor/assets.h"
#include "util/error.h"

namespace hexgait {
namespace {

// A creature of `particles` particles and `springs` springs: only the counts matter to the
// estimate.
CreatureModel OfSize(int particles, int springs) {
  CreatureModel model = LoadCreatureOrDefault("");
  model.mass.resize(particles, 0.01);
  model.spring_a.resize(springs, 0);
  return model;
}

// scripts/step_cost.sh on the AMD EPYC (Zen 5) the constants were taken from: ns per
// creature-step, one core, median of three; scalar is `simulate`, batched `evolve` in double.
// The estimate must never be above a measurement (it would refuse a run that finishes within
// the hour) nor more than 2x below it (a run of two hours would start unrefused).
TEST(WorkSize, TheEstimateIsWithinAFactorOfTwoOfMeasuredSteps) {
  struct Row {
    int particles, springs;
    double scalar_ns, batched_ns;
  };
  const Row rows[] = {{14, 40, 344.1, 44.25},        {100, 212, 1874.7, 262.81},
                      {300, 612, 5566.2, 772.87},    {1000, 2012, 18314.4, 3513.54},
                      {300, 1756, 13726.6, 2177.32}, {1000, 5956, 48758.6, 9698.77}};
  for (const Row& row : rows) {
    const CreatureModel model = OfSize(row.particles, row.springs);
    const double scalar = EstimatedSimulationSeconds(model, 1, 1e9, StepPath::kScalar);
    const double batched = EstimatedSimulationSeconds(model, 1, 1e9, StepPath::kBatched);
    SCOPED_TRACE(std::to_string(row.particles) + " particles, " + std::to_string(row.springs) +
                 " springs: estimated " + std::to_string(scalar) + " and " +
                 std::to_string(batched) + " ns per step");
    EXPECT_LE(scalar, row.scalar_ns);
    EXPECT_GE(scalar, row.scalar_ns / 2);
    EXPECT_LE(batched, row.batched_ns);
    EXPECT_GE(batched, row.batched_ns / 2);
  }
}

TEST(WorkSize, WorkersShareTheTimeAndTheHourIsTheLimit) {
  const CreatureModel hexapod = LoadCreatureOrDefault("");
  const double one = EstimatedSimulationSeconds(hexapod, 100, 4e5, StepPath::kBatched);
  EXPECT_DOUBLE_EQ(EstimatedSimulationSeconds(hexapod, 100, 4e5, StepPath::kBatched, 4), one / 4);
  EXPECT_NO_THROW(RefuseLongRun("x", kLongRunSeconds, false));
  EXPECT_THROW(RefuseLongRun("x", kLongRunSeconds * 1.01, false), InputError);
  EXPECT_NO_THROW(RefuseLongRun("x", 1e9, true));
}

}  // namespace
}  // namespace hexgait
