// The search driver and its optimizers: CMA-ES's determinism, bounds, defaults and resumption,
// the registry, and continuous genomes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "eval/evaluator.h"
#include "ga/checkpoint_json.h"
#include "ga/genome_io.h"
#include "motor/leg_targets.h"
#include "search/generational.h"
#include "search/search_driver.h"
#include "search/stored_results.h"
#include "sim/batch_evaluate.h"
#include "test_util.h"
#include "util/error.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct SearchFixture : ::testing::Test {
  CreatureModel model = test::DefaultCreature();
  MotorProgram program = LoadMotorProgramOrDefault("", model);

  EvolutionParams CmaEsParams(int threads = 1) const {
    EvolutionParams p;
    p.seed = 7;
    p.population = 0;  // Hansen's default
    p.generations = 3;
    p.settings = ParamValues::Defaults(*FindOptimizerKind("cmaes").params);
    p.threads = threads;
    p.run.duration = 20;  // short runs keep the test fast; the algorithm is the same
    return p;
  }
  std::unique_ptr<GenerationalOptimizer> Start(const EvolutionParams& p) const {
    return FindOptimizerKind("cmaes").start(SearchScene{model, program, ""}, p);
  }
  void Run(GenerationalOptimizer& search, int threads, int tells = -1) const {
    EvaluatorConfig config = EvaluatorConfigOf(search.params());
    config.threads = threads;
    const auto evaluator = MakeLocalEvaluator(model, program, config);
    const CandidateDecoder decoder(model, program, search.layout());
    for (int t = 0; t != tells && !search.Done(); ++t) SearchStep(search, *evaluator, decoder);
  }
};

// The state without wall times (which differ between runs) and the checksum over them.
nlohmann::json WithoutTimes(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  j.erase("checksum");
  for (auto& h : j["history"]) h.erase("seconds");
  return j;
}

TEST_F(SearchFixture, CmaEsUsesHansensDefaultPopulationAndStaysInTheGenesRange) {
  const auto search = Start(CmaEsParams());
  EXPECT_EQ(search->params().population, 18);  // 4 + floor(3 ln 120)
  EXPECT_EQ(search->budget(), 18 * 4);
  const Candidates& c = search->Ask();
  ASSERT_EQ(c.size(), 18u);
  ASSERT_EQ(c.dims, 120);
  const double step = program.gene_length_step;
  for (double x : c.offsets) {
    EXPECT_GE(x, kGeneMin * step);
    EXPECT_LE(x, kGeneMax * step);
  }
}

TEST_F(SearchFixture, CmaEsGivesTheSameBitsWhateverTheThreadCount) {
  const auto one = Start(CmaEsParams());
  const auto two = Start(CmaEsParams());
  Run(*one, 1);
  Run(*two, 2);
  ASSERT_TRUE(one->Done() && two->Done());
  EXPECT_EQ(WithoutTimes(one->Save()), WithoutTimes(two->Save()));
  EXPECT_EQ(one->result().total_evaluations, 18 * 4);
  EXPECT_TRUE(one->result().best->genome.continuous());
}

TEST_F(SearchFixture, CmaEsResumedFromAnyGenerationGivesTheSameBits) {
  const auto whole = Start(CmaEsParams());
  Run(*whole, 2);
  for (int stop_after = 1; stop_after <= 3; ++stop_after) {
    const auto first = Start(CmaEsParams());
    Run(*first, 2, stop_after);
    const std::string saved = first->Save();
    const OptimizerKind& kind = CheckpointKind(saved);
    ASSERT_STREQ(kind.name, "cmaes");
    bool unchecked = true;
    const auto resumed = kind.resume(SearchScene{model, program, ""}, saved, "saved", &unchecked);
    EXPECT_FALSE(unchecked);
    Run(*resumed, 2);
    EXPECT_EQ(WithoutTimes(resumed->Save()), WithoutTimes(whole->Save())) << stop_after;
  }
}

// A CMA-ES checkpoint as hexgait wrote it before "format_version" ("version", no
// "hexgait_version") still resumes, to the same bits as the run that was never interrupted.
TEST_F(SearchFixture, AnOldStyleCmaEsCheckpointResumesToTheSameBits) {
  const auto whole = Start(CmaEsParams());
  Run(*whole, 2);
  const auto first = Start(CmaEsParams());
  Run(*first, 2, 2);
  nlohmann::json old = nlohmann::json::parse(first->Save());
  EXPECT_EQ(old.at("format_version"), 1);
  EXPECT_EQ(old.at("hexgait_version"), HEXGAIT_VERSION);
  old["version"] = old.at("format_version");
  old.erase("format_version");
  old.erase("hexgait_version");
  old["checksum"] = Checksum(old);
  const std::string text = old.dump(1) + "\n";
  bool unchecked = true;
  const auto resumed =
      CheckpointKind(text).resume(SearchScene{model, program, ""}, text, "old", &unchecked);
  EXPECT_FALSE(unchecked);
  Run(*resumed, 2);
  EXPECT_EQ(WithoutTimes(resumed->Save()), WithoutTimes(whole->Save()));
}

TEST_F(SearchFixture, AnEditedCmaEsCheckpointIsRefused) {
  const auto search = Start(CmaEsParams());
  Run(*search, 2, 1);
  nlohmann::json j = nlohmann::json::parse(search->Save());
  j["step_size"] = j["step_size"].get<double>() * 2;
  const std::string edited = j.dump(1);
  EXPECT_THROW(
      {
        try {
          CheckpointKind(edited).resume(SearchScene{model, program, ""}, edited, "c.json", nullptr);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("checksum does not match"), std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
}

// A checkpoint whose checksum was recomputed after the edit still has to describe a search
// distribution: a covariance that is not positive definite would sample NaN offsets.
TEST_F(SearchFixture, ACmaEsCheckpointWithoutAPositiveDefiniteCovarianceIsRefused) {
  const auto search = Start(CmaEsParams());
  Run(*search, 2, 1);
  for (const double diagonal : {-1.0, 0.0}) {
    nlohmann::json j = nlohmann::json::parse(search->Save());
    j["covariance"][0] = diagonal;
    j["checksum"] = Checksum(j);
    const std::string edited = j.dump(1);
    try {
      CheckpointKind(edited).resume(SearchScene{model, program, ""}, edited, "c.json", nullptr);
      ADD_FAILURE() << "a covariance with diagonal " << diagonal << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("positive definite"), std::string::npos) << e.what();
    }
  }
}

TEST_F(SearchFixture, CmaEsRefusesBadSettings) {
  EvolutionParams p = CmaEsParams();
  p.population = 3;
  EXPECT_THROW(Start(p), InputError);
  p = CmaEsParams();
  p.settings.Set("sigma", 0, false);
  EXPECT_THROW(Start(p), InputError);
  // The GA's parameters are not CMA-ES's: refused by name, not ignored.
  p = CmaEsParams();
  p.settings = EvolutionParams().settings;
  try {
    Start(p);
    ADD_FAILURE() << "the GA's settings were accepted by cmaes";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a parameter of cmaes"), std::string::npos)
        << e.what();
  }
}

TEST_F(SearchFixture, TheRegistryNamesTheGaFirstAndRefusesUnknownNames) {
  ASSERT_GE(OptimizerKinds().size(), 2u);
  EXPECT_STREQ(OptimizerKinds().front()->name, "ga");
  try {
    FindOptimizerKind("nsga");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--algorithm 'nsga' is not one of ga, cmaes");
  }
  // Anything that is not a known checkpoint goes to the GA's reader, which says what is wrong.
  EXPECT_STREQ(CheckpointKind("not json").name, "ga");
}

TEST_F(SearchFixture, AskingTwiceGivesTheSameBatchAndTellChecksTheCount) {
  const auto search = Start(CmaEsParams());
  const std::vector<double> first = search->Ask().offsets;
  EXPECT_EQ(search->Ask().offsets, first);
  EXPECT_THROW(search->Tell(std::vector<RunResult>(3)), InputError);
}

// A Ctrl-C within a population: the evaluator starts no further batch and drops the results,
// so a stop comes within one batch (issue: a repertoire batch of 500 took seconds to stop).
// Slices: one vector of lanes per thread first, then sized from the time the last took; the
// caller hears from every slice and may end the work there; the results are one call's.
TEST_F(SearchFixture, SlicesGiveTheWholeCallsResultsAndACallerCanEndThem) {
  EvaluatorConfig config = EvaluatorConfigOf(CmaEsParams());
  config.threads = 2;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  std::vector<RestLengthTable> tables;
  for (int i = 0; i < 100; ++i) {
    const Genome g = test::RandomGenome(model, program, static_cast<uint64_t>(i));
    tables.push_back(PerturbedRestLengths(model, program, g));
  }
  const std::vector<RunResult> whole = evaluator->Evaluate(tables);
  std::vector<std::pair<int, int>> calls;
  // A slice of 1 microsecond: every slice is the smallest, 2 threads x 16 lanes.
  const std::vector<RunResult> sliced = EvaluateInSlices(
      *evaluator, tables, 2, 1e-6, [&](std::string_view, long long done, long long total) {
        calls.emplace_back(static_cast<int>(done), static_cast<int>(total));
      });
  ASSERT_EQ(sliced.size(), whole.size());
  for (size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(sliced[i].distance, whole[i].distance) << i;
    EXPECT_EQ(sliced[i].steps, whole[i].steps) << i;
  }
  const std::vector<std::pair<int, int>> expected{{32, 100}, {64, 100}, {96, 100}, {100, 100}};
  EXPECT_EQ(calls, expected);
  // A throw from the caller ends the work after that slice.
  int slices = 0;
  EXPECT_THROW(EvaluateInSlices(*evaluator, tables, 2, 1e-6,
                                [&](std::string_view, long long, long long) {
                                  if (++slices == 2) throw Stopped("enough");
                                }),
               Stopped);
  EXPECT_EQ(slices, 2);
}

// The driver's progress is the run's: evaluations told before plus those done in the batch, of
// the budget, never going back, and ending at the budget.
TEST_F(SearchFixture, TheDriversProgressCountsTheRunsEvaluationsToItsBudget) {
  const auto search = Start(CmaEsParams());
  EvaluatorConfig config = EvaluatorConfigOf(search->params());
  config.threads = 2;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  std::vector<std::pair<long long, long long>> calls;
  SearchHooks hooks;
  hooks.on_progress = [&](std::string_view stage, long long done, long long total) {
    EXPECT_EQ(stage, "evaluations");
    calls.emplace_back(done, total);
  };
  RunSearch(*search, *evaluator, CandidateDecoder(model, program, search->layout()), hooks);
  ASSERT_FALSE(calls.empty());
  for (size_t i = 0; i < calls.size(); ++i) {
    EXPECT_EQ(calls[i].second, search->budget());
    if (i > 0) {
      EXPECT_GE(calls[i].first, calls[i - 1].first);
    }
  }
  EXPECT_EQ(calls.back().first, search->budget());
  EXPECT_EQ(search->evaluations(), search->budget());
}

TEST_F(SearchFixture, AStopWithinAPopulationDropsItAfterTheBatchesUnderWay) {
  EvaluatorConfig config = EvaluatorConfigOf(CmaEsParams());
  config.threads = 2;
  config.batch_lanes = 1;  // one creature per batch: many stop points
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  const std::vector<RestLengthTable> tables(40, GeometricRestLengths(model, program));
  int calls = 0;
  try {
    evaluator->Evaluate(tables, [&](std::string_view, long long, long long) {
      if (++calls == 1) RequestStopForTesting(true);
    });
    RequestStopForTesting(false);
    FAIL() << "no EvaluationStopped";
  } catch (const EvaluationStopped& e) {
    RequestStopForTesting(false);
    EXPECT_LT(e.done, 40);
    EXPECT_EQ(e.total, 40);
  }
  // Without the stop, the same evaluator runs the population whole.
  EXPECT_EQ(evaluator->Evaluate(tables).size(), 40u);
}

// The same within one batch of lanes: the batch polls the stop every check interval, so a stop
// does not wait for a batch of 16 double lanes to finish (about a second on a slow core; CI saw
// a population of 400 take 2 s to stop).
TEST_F(SearchFixture, AStopWithinABatchOfLanesAbandonsIt) {
  const RestLengthTable table = GeometricRestLengths(model, program);
  const std::vector<RestLengthTable> tables(16, table);
  RunOptions options;
  options.duration = 100;
  int polls = 0;
  const auto stop_at_the_third = [&] { return ++polls == 3; };
  EXPECT_TRUE(EvaluateBatched(model, program, tables, options, 0, BatchIsa::kAuto,
                              Precision::kDouble, stop_at_the_third)
                  .empty());
  EXPECT_EQ(polls, 3);  // abandoned at once, 3 check intervals in
  // A poll that never stops changes no bit.
  const auto never = [] { return false; };
  const std::vector<RunResult> polled = EvaluateBatched(model, program, tables, options, 0,
                                                        BatchIsa::kAuto, Precision::kDouble, never);
  const std::vector<RunResult> plain = EvaluateBatched(model, program, tables, options);
  ASSERT_EQ(polled.size(), plain.size());
  for (size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(polled[i].distance, plain[i].distance);
    EXPECT_EQ(polled[i].steps, plain[i].steps);
  }

  EvaluatorConfig config = EvaluatorConfigOf(CmaEsParams());
  config.threads = 1;
  config.batch_lanes = 16;      // one batch: no stop point between batches
  config.run.duration = 10000;  // 4 million steps: seconds of work, even in a release build
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  const auto start = std::chrono::steady_clock::now();
  std::thread signal([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // into the batch
    RequestStopForTesting(true);
  });
  EXPECT_THROW(evaluator->Evaluate(tables), EvaluationStopped);
  signal.join();
  RequestStopForTesting(false);
  // One check interval after the stop, not the batch's end (a generous bound for sanitizers).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
}

// The search driver then saves the state after the last Tell, and the run resumed from it has
// the bits of one never stopped.
TEST_F(SearchFixture, ASearchStoppedWithinAPopulationResumesToTheSameBits) {
  const auto whole = Start(CmaEsParams());
  Run(*whole, 2);
  const auto first = Start(CmaEsParams());
  Run(*first, 2, 1);  // one generation told
  EvaluatorConfig config = EvaluatorConfigOf(first->params());
  config.threads = 2;
  config.batch_lanes = 1;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  SearchHooks hooks;
  std::string saved;
  hooks.save = [&](const std::string& state) { saved = state; };
  hooks.resume_hint = "; resume";
  hooks.on_progress = [](std::string_view, long long, long long) { RequestStopForTesting(true); };
  try {
    RunSearch(*first, *evaluator, CandidateDecoder(model, program, first->layout()), hooks);
    RequestStopForTesting(false);
    FAIL() << "not stopped";
  } catch (const EvaluationStopped&) {
    RequestStopForTesting(false);
    FAIL() << "the driver let the evaluator's stop through without saving";
  } catch (const Stopped& e) {
    RequestStopForTesting(false);
    EXPECT_NE(std::string(e.what()).find("were dropped and run again on resume; resume"),
              std::string::npos)
        << e.what();
  }
  ASSERT_FALSE(saved.empty());
  EXPECT_EQ(WithoutTimes(saved), WithoutTimes(first->Save()));
  bool unchecked = true;
  const auto resumed =
      CheckpointKind(saved).resume(SearchScene{model, program, ""}, saved, "saved", &unchecked);
  Run(*resumed, 2);
  EXPECT_EQ(WithoutTimes(resumed->Save()), WithoutTimes(whole->Save()));
}

// Stored results are replayed on resume, all of them or an even sample, and an edited one is
// named (issue: a checksum anyone can recompute let an edited elite through).
TEST_F(SearchFixture, StoredResultsReplayAndAnEditedOneIsNamed) {
  EvaluatorConfig config = EvaluatorConfigOf(CmaEsParams());
  config.threads = 2;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  const auto search = Start(CmaEsParams());
  const std::vector<RestLengthTable> tables =
      CandidateDecoder(model, program, search->layout()).Decode(search->Ask());
  const std::vector<RunResult> results = evaluator->Evaluate(tables);
  std::vector<StoredResult> stored;
  for (size_t i = 0; i < tables.size(); ++i) {
    stored.push_back({"individual " + std::to_string(i), tables[i], results[i]});
  }
  const ReplayCheck all = ReplayStoredResults(stored, *evaluator, "state.json");
  EXPECT_EQ(all.replayed, stored.size());
  EXPECT_EQ(all.stored, stored.size());
  const ReplayCheck some = ReplayStoredResults(stored, *evaluator, "state.json", 4);
  EXPECT_EQ(some.replayed, 4u);
  EXPECT_NE(some.Text("elites").find("replayed 4 of 18 stored elites (an even sample)"),
            std::string::npos);
  // The last is always in the sample: edit it, in the last bit of its distance.
  stored.back().result.distance = std::nextafter(stored.back().result.distance, 1e9);
  try {
    ReplayStoredResults(stored, *evaluator, "state.json", 4);
    FAIL() << "an edited result replayed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("state.json: individual 17 does not replay to its stored "
                                         "result (distance"),
              std::string::npos)
        << e.what();
  }
}

TEST(ContinuousGenome, FileRoundTripsEveryBitAndDecodesAsOffsets) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<double> offsets(static_cast<size_t>(layout->num_genes()));
  for (size_t g = 0; g < offsets.size(); ++g) offsets[g] = 0.001 * static_cast<double>(g) / 7.0;
  const Genome genome = Genome::FromOffsets(layout, offsets.data());
  const std::string text = FormatGenome(genome, "test");
  const Genome back = ParseGenome(text, "g.genome", layout);
  EXPECT_TRUE(back.continuous());
  EXPECT_EQ(back, genome);
  const RestLengthTable geometric = GeometricRestLengths(model, program);
  EXPECT_EQ(PerturbedRestLengths(model, program, back).length,
            OffsetRestLengths(geometric, model, *layout, offsets.data()).length);
  EXPECT_THROW(
      ParseGenome("layout full\nvalues offsets\nright_rear.hip_low swing nan\n", "g", layout),
      InputError);
}

}  // namespace
}  // namespace hexgait
