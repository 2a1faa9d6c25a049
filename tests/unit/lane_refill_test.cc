// Refilled lanes: a lane whose run ends takes the next creature at once, on its own clock.
// Every creature's result must be the bits of its one-creature run (EvaluateRestLengths in
// double, EvaluateBatched in float), for every lane count, instruction set and hand-out order,
// with falls (stop_at_fall), rest (early_stop) and divergence ending runs at different steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "eval/evaluator.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/leg_targets.h"
#include "same_result.h"
#include "sim/batch_evaluate.h"
#include "sim/evaluate.h"
#include "sim/lane_refill.h"
#include "test_util.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

using test::ExpectSameResult;

using test::SupportedIsas;

struct RefillFixture : ::testing::Test {
  CreatureModel model = test::DefaultCreature();
  MotorProgram program = LoadMotorProgramOrDefault("", model);

  // The unoptimised program, its extremes and random genomes: walkers and early fallers.
  std::vector<RestLengthTable> Tables(int randoms) const {
    const auto layout = MakeGenomeLayout(model, program, false);
    std::vector<RestLengthTable> tables;
    Genome plain(layout), low(layout), high(layout);
    for (int i = 0; i < low.num_genes(); ++i) {
      low.set_gene(i, -8);
      high.set_gene(i, 7);
    }
    for (const Genome* g : {&plain, &low, &high}) {
      tables.push_back(PerturbedRestLengths(model, program, *g));
    }
    for (int k = 0; k < randoms; ++k) {
      tables.push_back(
          PerturbedRestLengths(model, program, test::RandomGenome(model, program, 300 + k, 4242)));
    }
    return tables;
  }

  std::vector<RunResult> Refilled(const std::vector<RestLengthTable>& tables,
                                  const RunOptions& options, int lanes, BatchIsa isa,
                                  Precision precision, bool reversed = false) const {
    std::vector<RunResult> results(tables.size());
    int next = 0;
    const int n = static_cast<int>(tables.size());
    RefillStream stream;
    stream.claim = [&] {
      if (next >= n) return -1;
      const int i = next++;
      return reversed ? n - 1 - i : i;
    };
    EXPECT_TRUE(
        EvaluateRefilled(model, program, tables, options, lanes, results, stream, isa, precision));
    return results;
  }

  void ExpectEqualToOneCreatureRuns(const RunOptions& options, int randoms) const {
    const std::vector<RestLengthTable> tables = Tables(randoms);
    std::vector<RunResult> one;
    for (const RestLengthTable& t : tables) {
      one.push_back(EvaluateRestLengths(model, program, t, options));
    }
    std::vector<long long> ends;
    for (const RunResult& r : one) ends.push_back(r.steps);
    std::sort(ends.begin(), ends.end());
    ASSERT_GT(std::unique(ends.begin(), ends.end()) - ends.begin(), 3)
        << "runs must end at different steps, or refilling is not exercised";
    for (BatchIsa isa : SupportedIsas()) {
      for (int lanes : {1, 4, 8, 16}) {
        for (bool reversed : {false, true}) {
          SCOPED_TRACE(BatchIsaName(isa) + " x" + std::to_string(lanes) +
                       (reversed ? " reversed" : ""));
          const std::vector<RunResult> refilled =
              Refilled(tables, options, lanes, isa, Precision::kDouble, reversed);
          for (size_t i = 0; i < tables.size(); ++i) {
            ExpectSameResult(one[i], refilled[i], "refilled lane");
          }
        }
      }
    }
  }
};

TEST_F(RefillFixture, StopAtFallEqualsTheOneCreatureRunBitForBit) {
  RunOptions options;
  options.duration = 60;
  options.stop_at_fall = true;
  ExpectEqualToOneCreatureRuns(options, 21);
}

// Walkers end with a last chunk shorter than a check interval, with early_stop's rest checks
// on: the scalar loop's order of checks at the end.
TEST_F(RefillFixture, AShortLastChunkEqualsTheOneCreatureRun) {
  RunOptions options;
  options.duration = 60.1;  // not a whole number of check intervals
  options.stop_at_fall = true;
  options.early_stop = true;
  ExpectEqualToOneCreatureRuns(options, 13);
}

TEST_F(RefillFixture, DivergenceEqualsTheOneCreatureRun) {
  RunOptions options;
  options.duration = 30;
  options.dt = 0.011;  // past explicit Euler's limit: runs diverge, each at its own step
  ExpectEqualToOneCreatureRuns(options, 13);
}

// Float: refilled lanes give the bits of fixed float batches (the float path's reference).
TEST_F(RefillFixture, FloatEqualsFixedFloatBatches) {
  RunOptions options;
  options.duration = 60;
  options.stop_at_fall = true;
  const std::vector<RestLengthTable> tables = Tables(21);
  std::vector<RunResult> fixed;
  for (size_t i = 0; i < tables.size(); i += 8) {
    const size_t n = std::min<size_t>(8, tables.size() - i);
    for (const RunResult& r : EvaluateBatched(model, program, std::span(tables).subspan(i, n),
                                              options, 8, BatchIsa::kAuto, Precision::kFloat)) {
      fixed.push_back(r);
    }
  }
  for (BatchIsa isa : SupportedIsas()) {
    for (int lanes : {4, 16}) {
      SCOPED_TRACE(BatchIsaName(isa) + " x" + std::to_string(lanes));
      const std::vector<RunResult> refilled =
          Refilled(tables, options, lanes, isa, Precision::kFloat, true);
      for (size_t i = 0; i < tables.size(); ++i) {
        ExpectSameResult(fixed[i], refilled[i], "float lane");
      }
    }
  }
}

// RefilledLaneSteps: a lane-step for every lane of every step the kernel took, a running one
// for every step a creature took; each precision counted on its own.
TEST_F(RefillFixture, CountsTheLaneStepsSteppedAndThoseThatRanACreature) {
  RunOptions options;
  options.duration = 60;
  options.stop_at_fall = true;
  const std::vector<RestLengthTable> tables = Tables(9);  // 12 creatures, falling at various steps
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    const Precision other = precision == Precision::kFloat ? Precision::kDouble : Precision::kFloat;
    for (int lanes : {4, 16}) {
      SCOPED_TRACE(std::to_string(lanes) + " lanes");
      const LaneSteps before = RefilledLaneSteps(precision);
      const LaneSteps other_before = RefilledLaneSteps(other);
      const std::vector<RunResult> results =
          Refilled(tables, options, lanes, BatchIsa::kAuto, precision);
      const LaneSteps after = RefilledLaneSteps(precision);
      long long creature_steps = 0, longest = 0;
      for (const RunResult& r : results) {
        creature_steps += r.steps;
        longest = std::max(longest, r.steps);
      }
      EXPECT_EQ(after.running - before.running, creature_steps);
      const long long stepped = after.stepped - before.stepped;
      EXPECT_EQ(stepped % lanes, 0);
      if (lanes > static_cast<int>(tables.size())) {
        EXPECT_EQ(stepped, longest * lanes);  // every creature from step 0, the lanes to the last
      } else {
        EXPECT_GT(stepped, creature_steps);  // lanes wait empty once the tables run out
      }
      EXPECT_EQ(RefilledLaneSteps(other).stepped, other_before.stepped);
    }
  }
}

// Two streams sharing one counter, as the evaluator's threads do: the same results.
TEST_F(RefillFixture, StreamsOnTwoThreadsShareTheTables) {
  RunOptions options;
  options.duration = 60;
  options.stop_at_fall = true;
  const std::vector<RestLengthTable> tables = Tables(29);
  const std::vector<RunResult> one =
      Refilled(tables, options, 8, BatchIsa::kAuto, Precision::kDouble);
  std::vector<RunResult> shared(tables.size());
  std::atomic<int> next{0};
  std::atomic<int> finished{0};
  RefillStream stream;
  stream.claim = [&] {
    const int i = next.fetch_add(1);
    return i < static_cast<int>(tables.size()) ? i : -1;
  };
  stream.finished = [&](int) { finished.fetch_add(1); };
  std::thread other([&] { EvaluateRefilled(model, program, tables, options, 8, shared, stream); });
  EvaluateRefilled(model, program, tables, options, 8, shared, stream);
  other.join();
  EXPECT_EQ(finished.load(), static_cast<int>(tables.size()));
  for (size_t i = 0; i < tables.size(); ++i) ExpectSameResult(one[i], shared[i], "shared");
}

// Follow-ups: the local evaluator's float lanes hand the tables whose result is wanted to
// double lanes on the same threads as they finish. Every wanted table, and only those, is run
// in double, with the bits of its one-creature run, and the float results are Evaluate's, on
// one thread and on two.
TEST_F(RefillFixture, FollowUpsRunInDoubleBesideTheFloatLanes) {
  EvaluatorConfig config;
  config.run.duration = 60;
  config.run.stop_at_fall = true;
  config.precision = Precision::kFloat;
  const std::vector<RestLengthTable> tables = Tables(45);
  auto wanted = [](const RunResult& r) { return !r.fell && r.distance > 0.5; };
  for (int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    config.threads = threads;
    const std::unique_ptr<Evaluator> evaluator = MakeLocalEvaluator(model, program, config);
    const std::vector<RunResult> plain = evaluator->Evaluate(tables);
    FollowUps follow_ups;
    follow_ups.wanted = wanted;
    const std::vector<RunResult> first = evaluator->EvaluateWithFollowUps(tables, follow_ups);
    ASSERT_EQ(follow_ups.ran.size(), tables.size());
    int ran = 0;
    for (size_t i = 0; i < tables.size(); ++i) {
      ExpectSameResult(plain[i], first[i], "float result");
      ASSERT_EQ(follow_ups.ran[i] != 0, wanted(first[i])) << "table " << i;
      if (!follow_ups.ran[i]) continue;
      ++ran;
      ExpectSameResult(EvaluateRestLengths(model, program, tables[i], config.run),
                       follow_ups.in_double[i], "follow-up in double");
    }
    EXPECT_GT(ran, 2) << "too few follow-ups to exercise them";
    EXPECT_LT(ran, static_cast<int>(tables.size()) - 2) << "follow-ups must be a choice";
  }
}

// A stop while follow-ups run beside the float lanes, on two threads: the evaluation ends at
// once with EvaluationStopped (nothing half-told), and no thread is left waiting for
// follow-ups that will never come.
TEST_F(RefillFixture, AStopEndsFollowUpsOnEveryThread) {
  EvaluatorConfig config;
  config.run.duration = 5000;  // 2 million steps a creature: seconds of work
  config.run.stop_at_fall = true;
  config.precision = Precision::kFloat;
  config.threads = 2;
  const std::vector<RestLengthTable> tables = Tables(61);
  const std::unique_ptr<Evaluator> evaluator = MakeLocalEvaluator(model, program, config);
  FollowUps follow_ups;
  follow_ups.wanted = [](const RunResult&) { return true; };  // every faller, at once
  const auto start = std::chrono::steady_clock::now();
  std::thread signal([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // fallers confirming by now
    RequestStopForTesting(true);
  });
  EXPECT_THROW(evaluator->EvaluateWithFollowUps(tables, follow_ups), EvaluationStopped);
  signal.join();
  RequestStopForTesting(false);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

// A stop abandons the runs under way and says so.
TEST_F(RefillFixture, AStopEndsTheStream) {
  RunOptions options;
  options.duration = 60;
  const std::vector<RestLengthTable> tables = Tables(5);
  std::vector<RunResult> results(tables.size());
  int next = 0;
  RefillStream stream;
  stream.claim = [&] { return next < static_cast<int>(tables.size()) ? next++ : -1; };
  int polls = 0;
  stream.stop = [&] { return ++polls == 3; };
  EXPECT_FALSE(EvaluateRefilled(model, program, tables, options, 4, results, stream));
  EXPECT_EQ(polls, 3);
}

}  // namespace
}  // namespace hexgait
