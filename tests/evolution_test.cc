#include "ga/evolution.h"

#include <gtest/gtest.h>

#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

EvolutionParams ShortRun(int threads) {
  EvolutionParams p;
  p.seed = 3;
  p.population = 4;
  p.generations = 3;
  p.threads = threads;
  p.run.duration = 40;  // short runs keep the test fast; the GA logic is the same
  p.initial_mutation_rate = 0.05;
  return p;
}

TEST(Evolution, SameSeedSameBitsWhateverTheThreadCount) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const EvolutionResult one = Evolve(model, program, ShortRun(1), {});
  const EvolutionResult two = Evolve(model, program, ShortRun(2), {});
  const EvolutionResult three = Evolve(model, program, ShortRun(3), {});
  ASSERT_EQ(one.history.size(), 4u);
  for (size_t g = 0; g < one.history.size(); ++g) {
    EXPECT_EQ(one.history[g].best, two.history[g].best);
    EXPECT_EQ(one.history[g].mean, two.history[g].mean);
    EXPECT_EQ(one.history[g].worst, three.history[g].worst);
  }
  EXPECT_EQ(one.best->genome, two.best->genome);
  EXPECT_EQ(one.best->genome, three.best->genome);
}

TEST(Evolution, EliteKeepsTheBestFitness) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const EvolutionResult r = Evolve(model, program, ShortRun(2), {});
  for (size_t g = 1; g < r.history.size(); ++g) {
    EXPECT_GE(r.history[g].best, r.history[g - 1].best);
  }
  // Generation 0 evaluates everybody; later ones all but the elite.
  EXPECT_EQ(r.history[0].evaluations, 4);
  EXPECT_EQ(r.history[1].evaluations, 3);
  EXPECT_EQ(r.total_evaluations, 4 + 3 * 3);
}

TEST(Evolution, FirstIndividualIsTheUnoptimisedProgram) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  std::vector<Individual> first;
  EvolutionCallbacks callbacks;
  callbacks.on_generation = [&](const GenerationStats& g, const std::vector<Individual>& pop) {
    if (g.generation == 0) first = pop;
  };
  Evolve(model, program, ShortRun(1), callbacks);
  ASSERT_EQ(first.size(), 4u);
  for (int g = 0; g < first[0].genome.num_genes(); ++g) EXPECT_EQ(first[0].genome.gene(g), 0);
  bool any_mutated = false;
  for (size_t i = 1; i < first.size(); ++i)
    any_mutated = any_mutated || !(first[i].genome == first[0].genome);
  EXPECT_TRUE(any_mutated);
}

TEST(Evolution, RejectsBadParameters) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  EvolutionParams p = ShortRun(1);
  p.population = 1;
  EXPECT_THROW(Evolve(model, program, p, {}), InputError);
  p = ShortRun(1);
  p.generations = 0;
  EXPECT_THROW(Evolve(model, program, p, {}), InputError);
  p = ShortRun(1);
  p.mutation_rate = 1.5;
  EXPECT_THROW(Evolve(model, program, p, {}), InputError);
}

}  // namespace
}  // namespace hexgait
