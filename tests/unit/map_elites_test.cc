// MAP-Elites (ga/map_elites.h): the archive's binning and replacement, the same archive on any
// thread count, a resumed run equal to an uninterrupted one, the archive file refusing edits,
// and elites that replay exactly as the plain simulation runs them.
#include <gtest/gtest.h>
#include <functional>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "eval/evaluator.h"
#include "ga/behaviour.h"
#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "ga/genome_eval.h"
#include "ga/map_elites.h"
#include "ga/map_elites_checkpoint.h"
#include "search/archive_optimizer.h"
#include "sim/evaluate.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct ArchiveFixture {
  CreatureModel model = test::DefaultCreature();
  MotorProgram program = LoadMotorProgramOrDefault("", model);

  // A small run: 100 time units, before the unoptimised program falls, so many children stand.
  MapElitesParams Params(int threads) const {
    MapElitesParams p;
    p.seed = 5;
    p.evaluations = 90;
    p.batch = 20;
    p.bins = 3;
    p.threads = threads;
    p.run.duration = 100;
    p.run.stop_at_fall = true;
    return p;
  }
  MapElitesState Run(const MapElitesParams& p, const ArchiveCallbacks& callbacks = {}) const {
    MapElitesState state = StartArchiveSearch(p, model);
    const auto evaluator = MakeLocalEvaluator(model, program, EvaluatorConfigFor(p));
    RunArchiveSearch(model, program, *evaluator, state, callbacks);
    return state;
  }
};

// Callbacks that write the archive to *saved after the second batch, then stop the run.
ArchiveCallbacks SaveAndStopAfterTwoBatches(const ArchiveFixture& f, std::string* saved) {
  ArchiveCallbacks callbacks;
  callbacks.on_batch = [&f, saved](const MapElitesState& s) {
    if (s.batches == 2) {
      *saved = FormatArchive(s, SceneFingerprint(f.model, f.program));
      throw std::runtime_error("stop");
    }
  };
  return callbacks;
}

Elite EliteWith(const CreatureModel& model, const MotorProgram& program, double fitness) {
  Elite e{Genome(MakeGenomeLayout(model, program, false)), {}, fitness, 1};
  e.result.distance = fitness;
  return e;
}

// Everything but the wall-clock seconds.
void ExpectSameArchive(const MapElitesState& a, const MapElitesState& b) {
  ASSERT_EQ(a.evaluations, b.evaluations);
  ASSERT_EQ(a.batches, b.batches);
  ASSERT_EQ(a.archive.filled(), b.archive.filled());
  for (int cell : a.archive.filled()) {
    const Elite& x = *a.archive.at(cell);
    const Elite& y = *b.archive.at(cell);
    EXPECT_EQ(x.genome, y.genome) << "cell " << cell;
    EXPECT_EQ(x.fitness, y.fitness) << "cell " << cell;
    EXPECT_EQ(x.found_at, y.found_at) << "cell " << cell;
    EXPECT_EQ(x.result.foot_down_checks, y.result.foot_down_checks) << "cell " << cell;
  }
  ASSERT_EQ(a.history.size(), b.history.size());
  for (size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_EQ(a.history[i].filled, b.history[i].filled);
    EXPECT_EQ(a.history[i].qd_score, b.history[i].qd_score);
    EXPECT_EQ(a.history[i].best, b.history[i].best);
  }
}

TEST(Archive, BinsEachAxisAndClampsTheTop) {
  const Archive archive(3, 5);
  EXPECT_EQ(archive.cells(), 125);
  const double low[] = {0, 0, 0}, high[] = {1, 1, 1}, edge[] = {0.2, 0.39, 0.99};
  EXPECT_EQ(archive.CellOf(low), 0);
  EXPECT_EQ(archive.CellOf(high), 124);  // a duty factor of exactly 1 is in the last bin
  EXPECT_EQ(archive.CellOf(edge), 1 * 25 + 1 * 5 + 4);
  int bins[3];
  archive.BinsOf(1 * 25 + 1 * 5 + 4, bins);
  EXPECT_EQ(bins[0], 1);
  EXPECT_EQ(bins[1], 1);
  EXPECT_EQ(bins[2], 4);
}

TEST(Archive, KeepsTheFartherWalkerAndTheIncumbentOnATie) {
  const ArchiveFixture f;
  Archive archive(2, 2);
  EXPECT_EQ(archive.Best(), nullptr);
  EXPECT_TRUE(archive.Offer(3, EliteWith(f.model, f.program, 2.0)));
  EXPECT_FALSE(archive.Offer(3, EliteWith(f.model, f.program, 2.0)));
  EXPECT_FALSE(archive.Offer(3, EliteWith(f.model, f.program, 1.0)));
  EXPECT_TRUE(archive.Offer(1, EliteWith(f.model, f.program, -1.0)));
  EXPECT_TRUE(archive.Offer(3, EliteWith(f.model, f.program, 5.0)));
  EXPECT_EQ(archive.filled(), (std::vector<int>{3, 1}));  // in the order first filled
  EXPECT_EQ(archive.QdScore(), 5.0);                      // a negative distance adds nothing
  EXPECT_EQ(archive.Best()->fitness, 5.0);
}

TEST(Archive, AdmitsOnlyGaitsThatStand) {
  const ArchiveFixture f;
  Archive archive(6, 5);
  const BehaviourDescriptor& duty = FindBehaviourDescriptor("duty");
  Elite fallen = EliteWith(f.model, f.program, 3.0);
  fallen.result.fell = true;
  EXPECT_FALSE(OfferToArchive(archive, duty, f.model, std::move(fallen)));
  Elite diverged = EliteWith(f.model, f.program, 3.0);
  diverged.result.diverged = true;
  EXPECT_FALSE(OfferToArchive(archive, duty, f.model, std::move(diverged)));
  EXPECT_TRUE(archive.filled().empty());
}

TEST(Behaviour, DescriptorsMeasureDutyFactors) {
  const ArchiveFixture f;
  RunResult r;
  r.feet_samples = 10;
  for (int leg = 0; leg < 6; ++leg) r.foot_down_checks[leg] = leg + 2;
  double out[16];
  FindBehaviourDescriptor("duty").measure(f.model, r, out);
  for (int leg = 0; leg < 6; ++leg) EXPECT_EQ(out[leg], (leg + 2) / 10.0);
  const BehaviourDescriptor& pairs = FindBehaviourDescriptor("pairs");
  ASSERT_EQ(pairs.axes(f.model).size(), 3u);
  pairs.measure(f.model, r, out);
  // Each pair's mean: right rear (2 checks of 10) with left rear (5), and so on.
  EXPECT_DOUBLE_EQ(out[0], 0.35);
  EXPECT_DOUBLE_EQ(out[1], 0.45);
  EXPECT_DOUBLE_EQ(out[2], 0.55);
  EXPECT_THROW(FindBehaviourDescriptor("speed"), InputError);
}

TEST(MapElites, SameArchiveOnOneAndTwoThreads) {
  const ArchiveFixture f;
  const MapElitesState one = f.Run(f.Params(1));
  const MapElitesState two = f.Run(f.Params(2));
  EXPECT_GT(one.archive.filled().size(), 3u) << "too few standing gaits to test anything";
  ExpectSameArchive(one, two);
  EXPECT_EQ(one.evaluations, 90);
  EXPECT_EQ(one.batches, 5);  // 4 of 20 and the last of 10
}

TEST(MapElites, ResumedFromTheFileEqualsUninterrupted) {
  const ArchiveFixture f;
  const MapElitesParams p = f.Params(2);
  const MapElitesState whole = f.Run(p);
  std::string saved;
  const ArchiveCallbacks stop_after_two = SaveAndStopAfterTwoBatches(f, &saved);
  EXPECT_THROW(f.Run(p, stop_after_two), std::runtime_error);
  MapElitesState resumed = ParseArchive(saved, "saved", f.model, f.program);
  EXPECT_EQ(resumed.evaluations, 40);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(p));
  RunArchiveSearch(f.model, f.program, *evaluator, resumed);
  ExpectSameArchive(whole, resumed);
}

// archive.json as hexgait wrote it before "format_version" ("version", no "hexgait_version")
// still resumes, to the same archive as the run that was never interrupted.
TEST(MapElites, AnOldStyleArchiveResumesToTheSameArchive) {
  const ArchiveFixture f;
  const MapElitesParams p = f.Params(2);
  const MapElitesState whole = f.Run(p);
  std::string saved;
  const ArchiveCallbacks stop_after_two = SaveAndStopAfterTwoBatches(f, &saved);
  EXPECT_THROW(f.Run(p, stop_after_two), std::runtime_error);
  nlohmann::json old = nlohmann::json::parse(saved);
  EXPECT_EQ(old.at("format_version"), kArchiveVersion);
  EXPECT_EQ(old.at("hexgait_version"), HEXGAIT_VERSION);
  old["version"] = old.at("format_version");
  old.erase("format_version");
  old.erase("hexgait_version");
  old["checksum"] = Checksum(old);
  MapElitesState resumed = ParseArchive(old.dump(1) + "\n", "old", f.model, f.program);
  EXPECT_EQ(FormatArchive(resumed, SceneFingerprint(f.model, f.program)), saved);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(p));
  RunArchiveSearch(f.model, f.program, *evaluator, resumed);
  ExpectSameArchive(whole, resumed);
}

TEST(MapElites, ElitesReplayAsThePlainSimulation) {
  const ArchiveFixture f;
  const MapElitesState state = f.Run(f.Params(2));
  RunOptions plain;
  plain.duration = 100;  // no stop at the fall: the run `simulate` and the movie make
  for (int cell : state.archive.filled()) {
    const Elite& e = *state.archive.at(cell);
    const RunResult r = EvaluateGenome(f.model, f.program, e.genome, plain);
    EXPECT_FALSE(r.fell);
    EXPECT_EQ(r.distance, e.fitness) << "cell " << cell;
    EXPECT_EQ(r.foot_down_checks, e.result.foot_down_checks) << "cell " << cell;
  }
}

// Float with admissions confirmed in double: every elite holds its double result, so it replays
// bit for bit in the plain (double) simulation, and float's false admissions are counted.
MapElitesState RunConfirmed(const ArchiveFixture& f, const MapElitesParams& p,
                            const ArchiveCallbacks& callbacks = {}) {
  MapElitesState state = StartArchiveSearch(p, f.model);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(p));
  const auto in_double = MakeDoubleEvaluator(f.model, f.program, p);
  RunArchiveSearch(f.model, f.program, *evaluator, state, callbacks, in_double.get());
  return state;
}

MapElitesParams ConfirmedParams(const ArchiveFixture& f, int threads) {
  MapElitesParams p = f.Params(threads);
  p.precision = Precision::kFloat;
  p.confirm_in_double = true;
  return p;
}

TEST(MapElites, ConfirmedElitesHoldTheirDoubleResults) {
  const ArchiveFixture f;
  const MapElitesState state = RunConfirmed(f, ConfirmedParams(f, 2));
  ASSERT_FALSE(state.archive.filled().empty());
  RunOptions plain;
  plain.duration = 100;
  for (int cell : state.archive.filled()) {
    const Elite& e = *state.archive.at(cell);
    const RunResult r = EvaluateGenome(f.model, f.program, e.genome, plain);
    EXPECT_FALSE(r.fell) << "cell " << cell;
    EXPECT_EQ(r.distance, e.fitness) << "cell " << cell;
    EXPECT_EQ(r.foot_down_checks, e.result.foot_down_checks) << "cell " << cell;
  }
  const ArchiveStats& last = state.history.back();
  // Every elite was confirmed once at least; some confirmed children were then beaten.
  EXPECT_GE(last.confirmed, static_cast<long long>(state.archive.filled().size()));
  EXPECT_LE(last.confirmed, state.evaluations);
  EXPECT_LE(last.refuted, last.confirmed);
  // The same archive on one thread, and through the file and back.
  ExpectSameArchive(state, RunConfirmed(f, ConfirmedParams(f, 1)));
  const std::string text = FormatArchive(state, SceneFingerprint(f.model, f.program));
  const MapElitesState read = ParseArchive(text, "a", f.model, f.program);
  EXPECT_TRUE(read.params.confirm_in_double);
  EXPECT_EQ(read.history.back().confirmed, last.confirmed);
  EXPECT_EQ(read.history.back().refuted, last.refuted);
}

TEST(MapElites, AConfirmedRunResumesToTheSameArchive) {
  const ArchiveFixture f;
  const MapElitesParams p = ConfirmedParams(f, 2);
  const MapElitesState whole = RunConfirmed(f, p);
  std::string saved;
  const ArchiveCallbacks stop_after_two = SaveAndStopAfterTwoBatches(f, &saved);
  EXPECT_THROW(RunConfirmed(f, p, stop_after_two), std::runtime_error);
  MapElitesState resumed = ParseArchive(saved, "saved", f.model, f.program);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(p));
  const auto in_double = MakeDoubleEvaluator(f.model, f.program, p);
  RunArchiveSearch(f.model, f.program, *evaluator, resumed, {}, in_double.get());
  ExpectSameArchive(whole, resumed);
  EXPECT_EQ(resumed.history.back().confirmed, whole.history.back().confirmed);
}

TEST(MapElites, ConfirmingNeedsFloatAndADoubleEvaluator) {
  const ArchiveFixture f;
  MapElitesParams p = f.Params(1);
  p.confirm_in_double = true;  // in double: nothing to confirm
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
  MapElitesState state = StartArchiveSearch(ConfirmedParams(f, 1), f.model);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(state.params));
  try {
    RunArchiveSearch(f.model, f.program, *evaluator, state);
    ADD_FAILURE() << "told without a confirming evaluator";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("confirms admissions in double"), std::string::npos);
  }
  EXPECT_EQ(state.evaluations, 0);  // nothing told
}

TEST(MapElites, ShowcaseStartsWithTheFarthestAndPicksDistinctCells) {
  const ArchiveFixture f;
  const MapElitesState state = f.Run(f.Params(2));
  const BehaviourDescriptor& duty = FindBehaviourDescriptor("duty");
  const std::vector<int> chosen = ChooseShowcase(state.archive, duty, f.model, 4);
  ASSERT_FALSE(chosen.empty());
  EXPECT_EQ(state.archive.at(chosen[0])->fitness, state.archive.Best()->fitness);
  for (size_t i = 0; i < chosen.size(); ++i) {
    for (size_t j = 0; j < i; ++j) EXPECT_NE(chosen[i], chosen[j]);
  }
  EXPECT_TRUE(ChooseShowcase(Archive(6, 5), duty, f.model, 4).empty());
}

TEST(ArchiveFile, RefusesEditsOtherScenesAndMisplacedElites) {
  const ArchiveFixture f;
  const MapElitesState state = f.Run(f.Params(2));
  const std::string text = FormatArchive(state, SceneFingerprint(f.model, f.program));
  EXPECT_NO_THROW(ParseArchive(text, "a", f.model, f.program));
  const auto refused = [&](const std::string& edited, const std::string& why) {
    try {
      ParseArchive(edited, "a", f.model, f.program);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  // A changed seed keeps every field valid: only the checksum catches it.
  std::string seed = text;
  seed.replace(seed.find("\"seed\": \"5\""), 11, "\"seed\": \"6\"");
  refused(seed, "checksum");
  // An elite moved to another cell.
  nlohmann::json j = nlohmann::json::parse(text);
  j["elites"][0]["cell"] = j["elites"][0]["cell"].get<int>() + 1;
  refused(j.dump(), "not the cell of its result's behaviour");
  CreatureModel heavier = f.model;
  heavier.mass[0] *= 2;
  try {
    ParseArchive(text, "a", heavier, f.program);
    ADD_FAILURE() << "accepted another creature";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different creature"), std::string::npos);
  }
}

// CMA-MAE (search/cma_mae_optimizer.cc) through the same archive search: its emitters and
// thresholds travel in "algorithm_state", so a run resumed from any batch is the run never
// interrupted, on any thread count.
MapElitesParams CmaMaeParams(const ArchiveFixture& f, int threads) {
  MapElitesParams p = f.Params(threads);
  p.algorithm = "cma-mae";
  p.settings.Set("emitters", 4, true);
  return p;
}

// The run with `p` equals itself on 1 and 2 threads, and resumed from its file after two
// batches; returns the saved file's JSON.
nlohmann::json ExpectDeterministicAndResumable(const ArchiveFixture& f, MapElitesParams p) {
  p.threads = 1;
  const MapElitesState one = f.Run(p);
  p.threads = 2;
  const MapElitesState whole = f.Run(p);
  EXPECT_GT(one.archive.filled().size(), 3u) << "too few standing gaits to test anything";
  ExpectSameArchive(one, whole);
  EXPECT_EQ(one.algorithm_state, whole.algorithm_state);
  std::string saved;
  EXPECT_THROW(f.Run(p, SaveAndStopAfterTwoBatches(f, &saved)), std::runtime_error);
  MapElitesState resumed = ParseArchive(saved, "saved", f.model, f.program);
  EXPECT_EQ(FormatArchive(resumed, SceneFingerprint(f.model, f.program)), saved);
  const auto evaluator = MakeLocalEvaluator(f.model, f.program, EvaluatorConfigFor(p));
  RunArchiveSearch(f.model, f.program, *evaluator, resumed);
  ExpectSameArchive(whole, resumed);
  EXPECT_EQ(whole.algorithm_state, resumed.algorithm_state);
  return nlohmann::json::parse(saved);
}

TEST(CmaMae, IsDeterministicOnAnyThreadCountAndWhenResumed) {
  const ArchiveFixture f;
  const nlohmann::json saved = ExpectDeterministicAndResumable(f, CmaMaeParams(f, 2));
  EXPECT_EQ(saved.at("algorithm"), "cma-mae");
  EXPECT_EQ(saved.at("params").at("emitters"), 4);
  EXPECT_EQ(saved.at("algorithm_state").at("emitters").size(), 4u);
  EXPECT_FALSE(saved.at("algorithm_state").at("threshold_cells").empty());
}

// MAP-Elites with iso+line variation (search/iso_line_optimizer.cc): the same promises, and
// children that differ from plain MAP-Elites' (another operator, not another name).
TEST(IsoLine, IsDeterministicOnAnyThreadCountAndWhenResumed) {
  const ArchiveFixture f;
  MapElitesParams p = f.Params(2);
  p.algorithm = "iso-line";
  const nlohmann::json saved = ExpectDeterministicAndResumable(f, p);
  EXPECT_EQ(saved.at("algorithm"), "iso-line");
  EXPECT_EQ(saved.at("params").at("sigma_line"), 0.2);
  MapElitesParams plain = f.Params(2);
  const MapElitesState line = f.Run(p);
  EXPECT_NE(FormatArchive(line, SceneFingerprint(f.model, f.program)),
            FormatArchive(f.Run(plain), SceneFingerprint(f.model, f.program)));
}

// A saved state that does not fit the run (checksum recomputed, as anyone can) is refused by
// name when the search continues, not trusted.
TEST(CmaMae, RefusesASavedStateThatDoesNotFit) {
  const ArchiveFixture f;
  std::string saved;
  EXPECT_THROW(f.Run(CmaMaeParams(f, 1), SaveAndStopAfterTwoBatches(f, &saved)),
               std::runtime_error);
  const auto refused = [&](const std::function<void(nlohmann::json&)>& edit, const char* what) {
    nlohmann::json j = nlohmann::json::parse(saved);
    edit(j);
    j["checksum"] = Checksum(j);
    try {
      MapElitesState state = ParseArchive(j.dump(1), "a", f.model, f.program);
      MakeArchiveOptimizer(SearchScene{f.model, f.program, ""}, std::move(state));
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused([](nlohmann::json& j) { j["algorithm_state"]["emitters"].erase(0); },
          "one entry per emitter");
  refused([](nlohmann::json& j) { j["algorithm_state"]["threshold_cells"][0] = -1; },
          "increasing cells");
  refused([](nlohmann::json& j) { j["params"]["sigma"] = 0; }, "--sigma must be in");
  refused([](nlohmann::json& j) { j["params"]["mutation_rate"] = 0.5; },
          "--mutation-rate is not a parameter of cma-mae");
  refused(
      [](nlohmann::json& j) {
        for (auto& e : j["algorithm_state"]["emitters"]) {
          if (!e["distribution"].is_null()) e["distribution"]["covariance"][0] = -1.0;
        }
      },
      "positive definite");
}

TEST(CmaMae, NeedsTwoChildrenPerEmitter) {
  const ArchiveFixture f;
  MapElitesParams p = CmaMaeParams(f, 1);
  p.settings.Set("emitters", 11, true);  // a batch of 20
  try {
    MakeArchiveOptimizer(SearchScene{f.model, f.program, ""}, StartArchiveSearch(p, f.model));
    ADD_FAILURE() << "11 emitters accepted for a batch of 20";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--batch must be at least 2 x --emitters"),
              std::string::npos)
        << e.what();
  }
}

TEST(MapElites, RefusesBadParameters) {
  const ArchiveFixture f;
  MapElitesParams p = f.Params(1);
  p.bins = 11;  // 11^6 cells
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
  p = f.Params(1);
  p.descriptor = "nope";
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
  p = f.Params(1);
  p.batch = 0;
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
  p = f.Params(1);
  p.settings.Set("mutation_rate", 1.5, false);
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
  // A parameter of another optimizer is refused by name, not ignored.
  p = f.Params(1);
  p.settings.Set("sigma", 0.5, false);
  try {
    StartArchiveSearch(p, f.model);
    ADD_FAILURE() << "--sigma was accepted by map-elites";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--sigma is not a parameter of map-elites");
  }
  p = f.Params(1);
  p.algorithm = "nope";
  EXPECT_THROW(StartArchiveSearch(p, f.model), InputError);
}

}  // namespace
}  // namespace hexgait
