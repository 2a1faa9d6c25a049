// `hexgait adapt` as a library call (run/adapt_run.h): how it reports progress and lets its
// caller end the work, and how a diverged elite or trial is written down (counted apart, never
// as fallen or standing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run/adapt_run.h"
#include "run/repertoire_run.h"
#include "util/error.h"

namespace hexgait {
namespace {
namespace fs = std::filesystem;

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The rows of a CSV file as fields, the header first.
std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream text(ReadAll(path));
  for (std::string line; std::getline(text, line);) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

int Column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  return -1;
}

// One small repertoire for the suite (100 evaluations of 200 time units: under a second).
class AdaptRunFixture : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string pattern = (fs::temp_directory_path() / "hexgait_adapt_test.XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    root_ = pattern;
    RepertoireSettings settings;
    settings.params.evaluations = 100;
    settings.params.batch = 50;
    settings.time = 200;
    settings.no_movie = true;
    settings.out_dir = root_ + "/rep";
    RunRepertoire(settings);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static AdaptRequest Request() {
    AdaptRequest request;
    request.repertoire_dir = root_ + "/rep";
    request.damage = "right_middle:locked";
    request.threads = 2;
    return request;
  }
  static std::string root_;
};
std::string AdaptRunFixture::root_;

TEST_F(AdaptRunFixture, ProgressComesBetweenPiecesOfWorkAndTheCallerCanEndIt) {
  AdaptRequest request = Request();
  std::vector<std::string> stages;
  std::vector<std::pair<long long, long long>> counts;
  request.on_progress = [&](std::string_view stage, long long done, long long total) {
    stages.emplace_back(stage);
    counts.emplace_back(done, total);
  };
  const AdaptOutcome outcome = AdaptToDamage(request);
  // The archive replayed intact, every elite damaged (both in slices), then each trial before
  // it runs, then each GA generation.
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "elites replayed on the intact creature");
  size_t i = 0;
  while (i < stages.size() && stages[i] == "elites replayed on the intact creature") ++i;
  EXPECT_EQ(outcome.prior_check.replayed, outcome.cells.size());
  ASSERT_LT(i, stages.size());
  EXPECT_EQ(stages[i], "elites run on the damaged creature");
  while (i < stages.size() && stages[i] == "elites run on the damaged creature") ++i;
  EXPECT_EQ(counts[i - 1], std::make_pair(static_cast<long long>(outcome.cells.size()),
                                          static_cast<long long>(outcome.cells.size())));
  // Each trial before it runs and between its chunks of steps, under its own number.
  std::vector<int> numbers;
  for (; i < stages.size() && stages[i] == "trials"; ++i) {
    if (numbers.empty() || numbers.back() != counts[i].first) numbers.push_back(counts[i].first);
  }
  ASSERT_EQ(static_cast<int>(numbers.size()), outcome.trials());
  for (int t = 0; t < outcome.trials(); ++t) EXPECT_EQ(numbers[static_cast<size_t>(t)], t);
  // A trial is the same simulation as that elite's run among every elite's.
  for (int t = 0; t < outcome.trials(); ++t) {
    const RunResult& trial = outcome.trial_runs[static_cast<size_t>(t)];
    const RunResult& same =
        outcome.damaged[static_cast<size_t>(outcome.adaptation.trials[t].elite)];
    EXPECT_EQ(trial.distance, same.distance);
    EXPECT_EQ(trial.steps, same.steps);
  }
  ASSERT_LT(i, stages.size());
  for (size_t k = i; k < stages.size(); ++k) EXPECT_EQ(stages[k], "GA comparison generations");
  EXPECT_EQ(counts.back().first, counts.back().second);

  // Thrown from the progress call, a stop ends the work there: no further trial runs.
  int calls = 0;
  request.on_progress = [&](std::string_view stage, long long, long long) {
    ++calls;
    if (stage == "trials") throw Stopped("asked to");
  };
  EXPECT_THROW(AdaptToDamage(request), Stopped);
  const auto slices =
      std::count(stages.begin(), stages.end(), "elites run on the damaged creature") +
      std::count(stages.begin(), stages.end(), "elites replayed on the intact creature");
  EXPECT_EQ(calls, slices + 1);
}

// A diverged simulation has distance 0 and is neither a fall nor a standing gait: elites.csv,
// trials.csv and adapt.json say which diverged. (The damages cannot make the hexapod diverge
// at a step its repertoire stood at, so the outcome is marked by hand here.)
TEST_F(AdaptRunFixture, ADivergedEliteOrTrialIsWrittenAsDiverged) {
  const AdaptRequest request = Request();
  AdaptOutcome outcome = AdaptToDamage(request);
  ASSERT_GE(outcome.cells.size(), 2u);
  EXPECT_EQ(outcome.diverged(), 0);
  const int elite = outcome.adaptation.trials.front().elite;
  for (RunResult* r : {&outcome.damaged[static_cast<size_t>(elite)], &outcome.trial_runs[0]}) {
    r->diverged = true;
    r->fell = false;
    r->distance = 0;
  }
  EXPECT_EQ(outcome.diverged(), 1);
  const std::string out = root_ + "/adapt";
  WriteAdaptFolder(request, outcome, *TakeAdaptFolder(out));

  const auto elites = ReadCsv(out + "/elites.csv");
  const int diverged_column = Column(elites[0], "damaged_diverged");
  ASSERT_GE(diverged_column, 0);
  for (size_t e = 1; e < elites.size(); ++e) {
    EXPECT_EQ(elites[e][static_cast<size_t>(diverged_column)],
              static_cast<int>(e - 1) == elite ? "1" : "0");
  }
  const auto trials = ReadCsv(out + "/trials.csv");
  const int trial_column = Column(trials[0], "diverged");
  ASSERT_GE(trial_column, 0);
  EXPECT_EQ(trials[1][static_cast<size_t>(trial_column)], "1");
  const auto json = nlohmann::json::parse(ReadAll(out + "/adapt.json"));
  EXPECT_EQ(json["elites_diverged_on_damaged"], 1);
}

}  // namespace
}  // namespace hexgait
