#include "ga/roulette.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ga/rng.h"

namespace hexgait {
namespace {

TEST(Roulette, FrequenciesAreProportionalToFitness) {
  const std::vector<double> weights = {1, 2, 3, 4};
  const int draws = 200000;
  std::vector<int> count(weights.size(), 0);
  Rng rng(7);
  for (int i = 0; i < draws; ++i) ++count[RouletteSelect(weights, rng.NextDouble())];
  for (size_t i = 0; i < weights.size(); ++i) {
    const double p = weights[i] / 10.0;
    const double sigma = std::sqrt(draws * p * (1 - p));
    // 5 sigma: a correct implementation fails this about once in 3 million runs.
    EXPECT_NEAR(count[i], draws * p, 5 * sigma) << "slot " << i;
  }
}

TEST(Roulette, NegativeFitnessIsNeverChosen) {
  const std::vector<double> weights = {-5, 3, -1, 1};
  Rng rng(3);
  for (int i = 0; i < 10000; ++i) {
    const int k = RouletteSelect(weights, rng.NextDouble());
    EXPECT_TRUE(k == 1 || k == 3);
  }
}

TEST(Roulette, AllZeroIsUniform) {
  const std::vector<double> weights = {0, -1, 0, 0};
  std::vector<int> count(4, 0);
  Rng rng(11);
  for (int i = 0; i < 40000; ++i) ++count[RouletteSelect(weights, rng.NextDouble())];
  for (int c : count) EXPECT_NEAR(c, 10000, 500);
}

TEST(Roulette, EdgesOfTheWheel) {
  const std::vector<double> weights = {1, 0, 2};
  EXPECT_EQ(RouletteSelect(weights, 0.0), 0);
  EXPECT_EQ(RouletteSelect(weights, std::nextafter(1.0, 0.0)), 2);
  EXPECT_EQ(RouletteSelect(weights, 1.0 / 3.0 + 1e-12), 2);  // zero slot is skipped
}

TEST(Rng, IsReproducibleAndStreamsDiffer) {
  Rng a = Rng::ForStream(1, 5), b = Rng::ForStream(1, 5), c = Rng::ForStream(1, 6);
  const uint64_t first = a.NextU64();
  EXPECT_EQ(first, b.NextU64());
  EXPECT_NE(first, c.NextU64());
  Rng d(9);
  for (int i = 0; i < 1000; ++i) {
    const double u = d.NextDouble();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    EXPECT_LT(d.NextBelow(13), 13u);
  }
}

}  // namespace
}  // namespace hexgait
