// Checkpoints: a run continued from any generation's checkpoint, written to text and read
// back, gives the same bits as the run that was never interrupted; a checkpoint for another
// creature or a damaged one is refused with a clear error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "ga/evolution.h"
#include "search/ga_optimizer.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

EvolutionParams SmallRun() {
  EvolutionParams p;
  p.seed = 11;
  p.population = 4;
  p.generations = 4;
  p.threads = 2;
  p.run.duration = 60;
  return p;
}

void ExpectSameRun(const EvolutionResult& a, const EvolutionResult& b) {
  ASSERT_EQ(a.history.size(), b.history.size());
  for (size_t g = 0; g < a.history.size(); ++g) {
    EXPECT_EQ(a.history[g].best, b.history[g].best) << "generation " << g;
    EXPECT_EQ(a.history[g].mean, b.history[g].mean) << "generation " << g;
    EXPECT_EQ(a.history[g].worst, b.history[g].worst) << "generation " << g;
  }
  ASSERT_TRUE(a.best && b.best);
  EXPECT_TRUE(a.best->genome == b.best->genome);
  EXPECT_EQ(a.best->fitness, b.best->fitness);
  // The best's whole result comes through the checkpoint, its duty-factor counts included.
  EXPECT_EQ(a.best->result.feet_samples, b.best->result.feet_samples);
  EXPECT_EQ(a.best->result.foot_down_checks, b.best->result.foot_down_checks);
  EXPECT_GT(a.best->result.foot_down_checks[0], 0);
  EXPECT_EQ(a.total_evaluations, b.total_evaluations);
}

void CheckResumingFromEveryGeneration(Precision precision) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  EvolutionParams params = SmallRun();
  params.precision = precision;
  std::vector<std::string> checkpoints;
  EvolutionCallbacks save;
  save.on_checkpoint = [&](const EvolutionCheckpoint& c) {
    checkpoints.push_back(FormatCheckpoint(c, SceneFingerprint(model, program)));
  };
  const EvolutionResult whole = Evolve(model, program, params, save);
  ASSERT_EQ(checkpoints.size(), static_cast<size_t>(params.generations + 1));
  for (int g = 0; g < params.generations; ++g) {
    const EvolutionCheckpoint c = ParseCheckpoint(checkpoints[g], "test", model, program);
    EXPECT_EQ(c.generation, g);
    EXPECT_EQ(c.params.precision, precision);
    EvolutionParams resumed_params = c.params;
    resumed_params.threads = 1;  // a different thread count must not matter either
    const EvolutionResult resumed = Evolve(model, program, resumed_params, {}, &c);
    SCOPED_TRACE("resumed after generation " + std::to_string(g));
    ExpectSameRun(whole, resumed);
  }
}

TEST(Checkpoint, ResumingFromEveryGenerationGivesTheSameBits) {
  CheckResumingFromEveryGeneration(Precision::kDouble);
}

// Float lanes: the checkpoint keeps the precision, so a resumed run continues in float.
TEST(Checkpoint, ResumingAFloatRunGivesTheSameBits) {
  CheckResumingFromEveryGeneration(Precision::kFloat);
}

// The checkpoint text after generation 0 of a small run.
std::string FirstCheckpoint(const CreatureModel& model, const MotorProgram& program) {
  std::string text;
  EvolutionParams params = SmallRun();
  params.generations = 1;
  EvolutionCallbacks save;
  save.on_checkpoint = [&](const EvolutionCheckpoint& c) {
    if (text.empty()) text = FormatCheckpoint(c, SceneFingerprint(model, program));
  };
  Evolve(model, program, params, save);
  return text;
}

// A checkpoint as hexgait wrote it before "format_version": the format's version as "version",
// no program version.
std::string AsOldCheckpoint(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  j["version"] = j.at("format_version");
  j.erase("format_version");
  j.erase("hexgait_version");
  j["checksum"] = Checksum(j);
  return j.dump(1) + "\n";
}

// Today's checkpoints say "format_version" and "hexgait_version"; an older one still resumes, to
// the same bits as the run that was never interrupted, and is written back as today's file.
TEST(Checkpoint, AnOldStyleCheckpointResumesToTheSameBits) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const EvolutionParams params = SmallRun();
  std::vector<std::string> checkpoints;
  EvolutionCallbacks save;
  save.on_checkpoint = [&](const EvolutionCheckpoint& c) {
    checkpoints.push_back(FormatCheckpoint(c, SceneFingerprint(model, program)));
  };
  const EvolutionResult whole = Evolve(model, program, params, save);
  ASSERT_GE(checkpoints.size(), 2u);
  const nlohmann::json today = nlohmann::json::parse(checkpoints[1]);
  EXPECT_EQ(today.at("format_version"), kCheckpointVersion);
  EXPECT_EQ(today.at("hexgait_version"), HEXGAIT_VERSION);
  EXPECT_FALSE(today.contains("version"));
  const std::string old = AsOldCheckpoint(checkpoints[1]);
  ASSERT_NE(old.find("\"version\": 2"), std::string::npos);
  bool unchecked = true;
  const EvolutionCheckpoint c = ParseCheckpoint(old, "old.json", model, program, &unchecked);
  EXPECT_FALSE(unchecked);  // a version 2 file's checksum is checked under either key
  EXPECT_EQ(FormatCheckpoint(c, SceneFingerprint(model, program)), checkpoints[1]);
  const EvolutionResult resumed = Evolve(model, program, c.params, {}, &c);
  ExpectSameRun(whole, resumed);
  // Both keys at once is no file hexgait wrote.
  nlohmann::json both = today;
  both["version"] = 2;
  both["checksum"] = Checksum(both);
  EXPECT_THROW(ParseCheckpoint(both.dump(1), "both.json", model, program), InputError);
}

TEST(Checkpoint, RefusesAnotherCreature) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const std::string text = FirstCheckpoint(model, program);
  CreatureModel stiffer = model;
  stiffer.stiffness[3] *= 1.01;
  try {
    ParseCheckpoint(text, "ck.json", stiffer, program);
    FAIL() << "a checkpoint of another creature was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different creature or motor program"), std::string::npos)
        << e.what();
  }
  MotorProgram slower = program;
  slower.transition_time += 1;
  EXPECT_THROW(ParseCheckpoint(text, "ck.json", model, slower), InputError);
}

TEST(Checkpoint, RefusesDamagedFiles) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const std::string text = FirstCheckpoint(model, program);
  const auto refused = [&](const std::string& damaged, const std::string& words) {
    try {
      ParseCheckpoint(damaged, "ck.json", model, program);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "not one line";
    }
  };
  refused(text.substr(0, text.size() / 2), "ck.json");  // truncated
  refused("", "ck.json");                               // empty
  refused("[1, 2]", "not a checkpoint");                // wrong type
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  refused(replace("\"population\": 4", "\"population\": 1"), "--population must be at least 2");
  refused(replace("\"format_version\": 2", "\"format_version\": 9"), "version 9 is not supported");
  refused(replace("\"generation\": 0", "\"generation\": 7"), "'generation' must be in");
  refused(replace("\"genes\": [", "\"genes\": [9,"), "genes");
  refused(replace("\"precision\": \"double\"", "\"precision\": \"half\""), "'precision' must be");
}

}  // namespace
// Integrity: any edit is refused, by the consistency checks (with a precise message) or else by
// the checksum; a version 1 file without a checksum is accepted after the consistency checks.
TEST(Checkpoint, RefusesInconsistentContent) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const nlohmann::json original = nlohmann::json::parse(FirstCheckpoint(model, program));
  const auto refused = [&](const std::function<void(nlohmann::json&)>& edit,
                           const std::string& words) {
    nlohmann::json j = original;
    edit(j);
    try {
      ParseCheckpoint(j.dump(1), "ck.json", model, program);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused([](nlohmann::json& j) { j["params"]["mutation_rate"] = 0.5; }, "checksum does not match");
  refused([](nlohmann::json& j) { j["population"][0]["fitness"] = "inf"; }, "not a finite number");
  refused([](nlohmann::json& j) { j["population"][0]["fitness"] = 1e9; },
          "does not match its result");
  refused([](nlohmann::json& j) { j["history"][0]["best"] = 1e9; },
          "the last history entry does not match the population");
  refused([](nlohmann::json& j) { j["total_evaluations"] = 99; },
          "'total_evaluations' is not the sum");
  refused([](nlohmann::json& j) { j.erase("checksum"); }, "missing field 'checksum'");
  // A version 1 file: no checksum; accepted, and the caller is told it could not be verified.
  nlohmann::json old = original;
  old.erase("checksum");
  old.erase("format_version");  // the older key for the format's version
  old.erase("hexgait_version");
  old["version"] = 1;
  bool unchecked = false;
  ParseCheckpoint(old.dump(1), "ck.json", model, program, &unchecked);
  EXPECT_TRUE(unchecked);
  ParseCheckpoint(original.dump(1), "ck.json", model, program, &unchecked);
  EXPECT_FALSE(unchecked);
}

}  // namespace hexgait
