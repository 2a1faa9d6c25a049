// repertoire.json as a typed record: what `repertoire` writes reads back field for field and
// dumps to the same text, a file from before the later keys still reads, and a file that is no
// repertoire.json is refused naming it.
#include "record/repertoire_record.h"

#include <gtest/gtest.h>

#include <string>

#include "util/error.h"

namespace hexgait {
namespace {

RepertoireRecord ExampleRepertoire() {
  RepertoireRecord r;
  r.seed = 18446744073709551615ull;  // every bit of a 64-bit seed, written as a string
  r.descriptor = "duty-factors";
  r.axes = {"L1", "L2", "L3", "R1", "R2", "R3"};
  r.bins = 5;
  r.cells = 15625;
  r.threads = 2;
  r.ranks = 1;
  r.time = 1000;
  r.dt = 0.0025;
  r.methods = {{"MAP-Elites", 2000, 41, 123.25 + 1e-13, 6.5, 7.75, 1.5},
               {"paper's GA, population 100", 2000, 12, 50.5, 5.25, 8.0, 1.25}};
  r.showcase = {{17, "elites/elite-1.genome", 6.5, {0.5, 0.75, 1, 0.25, 0.5, 0.125}, 1234}};
  r.movie = RepertoireMovieRecord{"grid.mp4", 30, 901};
  r.machine_use = MachineUseRecord{10.25, 19.5, 4000000, 3700000, 800000, 600001};
  r.wall_seconds = 12.5;
  return r;
}

TEST(RepertoireRecord, ReadsBackWhatItWrites) {
  const RepertoireRecord r = ExampleRepertoire();
  const std::string text = RepertoireRecordJson(r).dump(2) + "\n";
  const RepertoireRecord back = ParseRepertoireRecord(text, "repertoire.json");
  EXPECT_EQ(back.seed, r.seed);
  EXPECT_EQ(back.axes, r.axes);
  EXPECT_EQ(back.cells, 15625);
  ASSERT_EQ(back.methods.size(), 2u);
  EXPECT_EQ(back.methods[0].qd_score, r.methods[0].qd_score);  // bit for bit
  EXPECT_EQ(back.methods[1].name, "paper's GA, population 100");
  ASSERT_EQ(back.showcase.size(), 1u);
  EXPECT_EQ(back.showcase[0].duty_factors, r.showcase[0].duty_factors);
  EXPECT_EQ(back.showcase[0].found_at, 1234);
  ASSERT_TRUE(back.movie.has_value());
  EXPECT_EQ(back.movie->frames, 901);
  ASSERT_TRUE(back.machine_use.has_value());
  EXPECT_EQ(back.machine_use->cpu_seconds, 19.5);
  EXPECT_EQ(back.machine_use->float_lane_steps_running, 3700000);
  EXPECT_EQ(back.machine_use->double_lane_steps_running, 600001);
  EXPECT_EQ(RepertoireRecordJson(back).dump(2) + "\n", text);
  EXPECT_TRUE(RepertoireRecordJson(r)["seed"].is_string());
  EXPECT_EQ(RepertoireRecordJson(r)["hexgait_version"], HEXGAIT_VERSION);
}

// The keys as 'hexgait repertoire' wrote them before the record (its first version): the
// writer must keep them, in this order and with these types.
TEST(RepertoireRecord, WritesTheKeysItAlwaysWrote) {
  RepertoireRecord r = ExampleRepertoire();
  r.showcase.clear();
  r.movie.reset();
  r.machine_use.reset();
  const nlohmann::json j = RepertoireRecordJson(r);
  std::string keys;
  for (const auto& [key, value] : j.items()) keys += key + " ";
  EXPECT_EQ(keys,
            "algorithm axes bins cells command descriptor dt hexgait_version methods precision "
            "ranks seed settings threads time wall_seconds ");
  EXPECT_EQ(j["command"], "hexgait repertoire");
  EXPECT_EQ(j["methods"][0].dump(),
            R"({"best_fitness":7.75,"best_standing":6.5,"diverged":0,"evaluations":2000,)"
            R"("filled":41,"name":"MAP-Elites","qd_score":123.2500000000001,"seconds":1.5})");
}

TEST(RepertoireRecord, ReadsAnOlderFileWithoutTheLaterKeys) {
  const RepertoireRecord r = ParseRepertoireRecord(
      R"({"command": "hexgait repertoire", "seed": "3", "bins": 4, "cells": 4096,
          "methods": [{"name": "MAP-Elites", "evaluations": 100, "filled": 9,
                       "qd_score": 20.5, "best_standing": 3.25}]})",
      "old/repertoire.json");
  EXPECT_EQ(r.seed, 3u);
  EXPECT_EQ(r.hexgait_version, "");
  EXPECT_EQ(r.ranks, 1);
  EXPECT_EQ(r.precision, "double");
  ASSERT_EQ(r.methods.size(), 1u);
  EXPECT_EQ(r.methods[0].best_fitness, 0);
  EXPECT_TRUE(r.showcase.empty());
  EXPECT_FALSE(r.movie.has_value());
  EXPECT_FALSE(r.machine_use.has_value());
}

TEST(RepertoireRecord, RefusesAFileWithoutMethodsNamingIt) {
  try {
    ParseRepertoireRecord(R"({"seed": "1"})", "out/repertoire/repertoire.json");
    FAIL() << "accepted a repertoire.json without methods";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind("out/repertoire/repertoire.json: not a repertoire.json", 0), 0u)
        << e.what();
  }
  // A seed is its decimal digits and nothing else, within 64 bits: std::stoull read "-1" as
  // 2^64 - 1 and "12abc" as 12.
  for (const char* seed : {"x", "-1", "12abc", " 7", "+7", "", "18446744073709551616", "1.5"}) {
    EXPECT_THROW(ParseRepertoireRecord(std::string(R"({"seed": ")") + seed + R"(", "methods": []})",
                                       "x.json"),
                 InputError)
        << "seed \"" << seed << '"';
  }
  EXPECT_EQ(
      ParseRepertoireRecord(R"({"seed": "18446744073709551615", "methods": []})", "x.json").seed,
      18446744073709551615ULL);
  EXPECT_EQ(ParseRepertoireRecord(R"({"seed": 42, "methods": []})", "x.json").seed, 42u);
  EXPECT_THROW(ParseRepertoireRecord("[1, 2]", "x.json"), InputError);
}

// machine_use is optional, but one that is there must be whole: counts that cannot be, or a
// missing part, are refused naming the file.
TEST(RepertoireRecord, RefusesAMachineUseThatCannotBe) {
  const std::string head = R"({"methods": [], "machine_use": {"seconds": 2, "cpu_seconds": 3, )";
  const std::string lanes = R"("lane_steps": {"double": {"stepped": 8, "running": 4}, )";
  EXPECT_TRUE(
      ParseRepertoireRecord(head + lanes + R"("float": {"stepped": 16, "running": 9}}}})", "a.json")
          .machine_use.has_value());
  for (const std::string& bad :
       {head + lanes + R"("float": {"stepped": 16, "running": -9}}}})",
        head + lanes + R"("float": {"stepped": 16}}}})", head + R"("lane_steps": {}}})",
        std::string(R"({"methods": [], "machine_use": {"lane_steps": {}}})")}) {
    try {
      ParseRepertoireRecord(bad, "out/r/repertoire.json");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("out/r/repertoire.json: ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace hexgait
