#include "ga/evolution.h"
#include "search/ga_optimizer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "ga/checkpoint.h"
#include "sim/batch_kernel.h"
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
  p.settings.Set("initial_mutation_rate", 0.05, false);
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

TEST(Evolution, AStartGenomeIsTheFirstIndividualAndSurvivesACheckpoint) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  EvolutionParams params = ShortRun(1);
  const Genome start = test::RandomGenome(model, program, 7);
  params.start = start.genes();
  std::vector<Individual> first;
  std::string saved;
  EvolutionCallbacks callbacks;
  callbacks.on_generation = [&](const GenerationStats& g, const std::vector<Individual>& pop) {
    if (g.generation == 0) first = pop;
  };
  callbacks.on_checkpoint = [&](const EvolutionCheckpoint& c) {
    if (c.generation == 0) saved = FormatCheckpoint(c, SceneFingerprint(model, program));
  };
  const EvolutionResult whole = Evolve(model, program, params, callbacks);
  ASSERT_EQ(first.size(), 4u);
  EXPECT_TRUE(first[0].genome == start);
  EXPECT_FALSE(first[1].genome == start);  // its mutants
  // The start is part of the run's parameters: a resumed run keeps it and gives the same bits.
  const EvolutionCheckpoint c = ParseCheckpoint(saved, "test", model, program);
  EXPECT_EQ(c.params.start, params.start);
  const EvolutionResult resumed = Evolve(model, program, c.params, {}, &c);
  EXPECT_EQ(whole.best->fitness, resumed.best->fitness);
  EXPECT_TRUE(whole.best->genome == resumed.best->genome);
  params.start.pop_back();
  EXPECT_THROW(Evolve(model, program, params, {}), InputError);
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
  p.settings.Set("mutation_rate", 1.5, false);
  EXPECT_THROW(Evolve(model, program, p, {}), InputError);
}

}  // namespace
}  // namespace hexgait

namespace hexgait {
namespace {

// Every generation's best, mean and worst, and the best genome, are the same bits.
void ExpectSameHistory(const EvolutionResult& r, const EvolutionResult& expected) {
  ASSERT_EQ(r.history.size(), expected.history.size());
  for (size_t g = 0; g < r.history.size(); ++g) {
    EXPECT_EQ(r.history[g].best, expected.history[g].best) << "generation " << g;
    EXPECT_EQ(r.history[g].mean, expected.history[g].mean) << "generation " << g;
    EXPECT_EQ(r.history[g].worst, expected.history[g].worst) << "generation " << g;
  }
  EXPECT_EQ(r.best->genome, expected.best->genome);
}

// A run small enough to repeat with many batch widths, one creature per batch.
EvolutionParams OneCreaturePerBatch(Precision precision) {
  EvolutionParams p = ShortRun(1);
  p.population = 6;
  p.generations = 2;
  p.precision = precision;
  p.batch_lanes = 1;
  return p;
}

// Batching is an implementation detail: any batch width and thread count gives the same bits
// as the scalar path (batch_lanes 1).
TEST(Evolution, SameBitsWhateverTheBatchWidthAndThreadCount) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const EvolutionParams base = OneCreaturePerBatch(Precision::kDouble);
  const EvolutionResult scalar = Evolve(model, program, base, {});
  for (const auto& [lanes, threads] : {std::pair{0, 1}, {0, 2}, {2, 1}, {4, 3}, {16, 2}}) {
    SCOPED_TRACE("batch_lanes " + std::to_string(lanes) + ", threads " + std::to_string(threads));
    EvolutionParams p = base;
    p.batch_lanes = lanes;
    p.threads = threads;
    ExpectSameHistory(Evolve(model, program, p, {}), scalar);
  }
}

// Float runs are deterministic too: the same bits for any batch width and thread count, and
// not double's bits (batch_lanes 1 is float's reference here, not the scalar double path).
// Where the CPU has AVX-512, batches of up to 4 (batch_lanes 1 and 4, and 3 per thread with 2
// threads) run on the creature kernel and larger ones in float lanes, so this also checks that
// the two kernels agree.
TEST(Evolution, FloatRunsGiveTheSameBitsWhateverTheBatchWidthAndThreadCount) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const EvolutionParams base = OneCreaturePerBatch(Precision::kFloat);
  const EvolutionResult one = Evolve(model, program, base, {});
  EvolutionParams in_double = base;
  in_double.precision = Precision::kDouble;
  EXPECT_NE(Evolve(model, program, in_double, {}).history[0].mean, one.history[0].mean);
  for (const auto& [lanes, threads] : {std::pair{0, 1}, {0, 2}, {4, 3}, {16, 2}}) {
    SCOPED_TRACE("batch_lanes " + std::to_string(lanes) + ", threads " + std::to_string(threads));
    EvolutionParams p = base;
    p.batch_lanes = lanes;
    p.threads = threads;
    ExpectSameHistory(Evolve(model, program, p, {}), one);
  }
  EvolutionParams rk4 = base;
  rk4.run.integrator = IntegratorKind::kRk4;
  EXPECT_THROW(Evolve(model, program, rk4, {}), InputError);
}

TEST(Evolution, BatchPlanCoversEveryPendingIndividual) {
  for (int pending : {1, 3, 4, 17, 100}) {
    for (int threads : {1, 2, 7}) {
      for (int lanes : {0, 1, 3, 16}) {
        for (bool creature_kernel : {false, true}) {
          const std::vector<int> sizes =
              PlanBatches(pending, threads, lanes, Precision::kFloat, creature_kernel);
          int sum = 0;
          for (int s : sizes) {
            EXPECT_GE(s, 1);
            EXPECT_LE(s, lanes == 0 ? kMaxBatchLanes : lanes);
            sum += s;
          }
          EXPECT_EQ(sum, pending);
        }
      }
    }
  }
  // The paper's generation of 3 on 2 threads: one 4-lane batch, or with the creature kernel
  // (where a creature fills the vectors alone) 2 + 1 over both threads.
  EXPECT_EQ(PlanBatches(3, 2, 0, Precision::kFloat, false), std::vector<int>({3}));
  EXPECT_EQ(PlanBatches(3, 2, 0, Precision::kFloat, true), std::vector<int>({2, 1}));
  EXPECT_EQ(PlanBatches(3, 2, 0, Precision::kDouble, true), std::vector<int>({3}));
  // Many creatures: batches as wide as the instruction set runs best (16 float lanes with
  // AVX-512, 8 with AVX2), never wider, as even as possible (40 in 16-lane batches: 14, 13, 13).
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    SCOPED_TRACE(PrecisionName(precision));
    const int preferred = PreferredBatchLanes(BatchIsa::kAuto, precision);
    EXPECT_GE(preferred, NativeBatchLanes(BatchIsa::kAuto, precision));
    EXPECT_LE(preferred, kMaxBatchLanes);
    for (int s : PlanBatches(32 * preferred, 2, 0, precision, false)) EXPECT_EQ(s, preferred);
    const std::vector<int> forty = PlanBatches(40, 2, 0, precision, true);
    EXPECT_EQ(static_cast<int>(forty.size()), (40 + preferred - 1) / preferred);
    EXPECT_LE(*std::max_element(forty.begin(), forty.end()) -
                  *std::min_element(forty.begin(), forty.end()),
              1);
  }
  EXPECT_EQ(PreferredBatchLanes(BatchIsa::kGeneric, Precision::kFloat), 4);
  if (BatchIsaSupported(BatchIsa::kAvx2)) {
    EXPECT_EQ(PreferredBatchLanes(BatchIsa::kAvx2, Precision::kDouble), 4);
    EXPECT_EQ(PreferredBatchLanes(BatchIsa::kAvx2, Precision::kFloat), 8);
  }
  if (BatchIsaSupported(BatchIsa::kAvx512)) {
    EXPECT_EQ(PreferredBatchLanes(BatchIsa::kAvx512, Precision::kDouble), 16);
    EXPECT_EQ(PreferredBatchLanes(BatchIsa::kAvx512, Precision::kFloat), 16);
  }
}

}  // namespace
}  // namespace hexgait
