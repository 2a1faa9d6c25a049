// adapt.json's checked reader: what `report --adapt` reads is refused with one line naming the
// file and the member when it is not what `hexgait adapt` wrote.
#include "record/adapt_record.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "util/error.h"

namespace hexgait {
namespace {

// adapt.json as `hexgait adapt` wrote it: before it kept its scene (adapt.json), or after.
nlohmann::json Written(const char* file = "adapt.json") {
  std::ifstream in(std::string(HEXGAIT_SOURCE_DIR) + "/tests/fuzz/corpus/adapt_record/" + file);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

TEST(AdaptRecord, ReadsWhatAdaptWrote) {
  const nlohmann::json j = Written();
  const AdaptSummary a = ParseAdaptSummary(j.dump(), "adapt.json");
  EXPECT_EQ(a.damage, j["damage"]);
  EXPECT_EQ(a.trials, j["trials"]);
  EXPECT_EQ(a.adapted, j["adapted"]["distance"].get<double>());
  EXPECT_EQ(a.best_elite, j["best_elite_on_damaged"]["distance"].get<double>());
}

// The repertoire's intact scene, which a consumer of the folder compares with other folders'
// (report): read back whole; a file from before it has none, and says so.
TEST(AdaptRecord, ReadsTheScene) {
  const nlohmann::json j = Written("adapt_with_scene.json");
  const AdaptSummary a = ParseAdaptSummary(j.dump(), "adapt.json");
  ASSERT_TRUE(a.has_scene);
  EXPECT_EQ(a.scene.creature, j["scene"]["creature"]);
  EXPECT_EQ(a.scene.dt, j["scene"]["dt"].get<double>());
  EXPECT_EQ(a.scene.fingerprint, j["scene"]["scene_fingerprint"]);
  EXPECT_EQ(a.repertoire, j["repertoire"]);
  EXPECT_FALSE(ParseAdaptSummary(Written().dump(), "adapt.json").has_scene);
  nlohmann::json bad = j;
  bad["scene"]["dt"] = "0.0025";
  EXPECT_THROW(ParseAdaptSummary(bad.dump(), "adapt.json"), InputError);
  bad = j;
  bad["scene"].erase("scene_fingerprint");
  EXPECT_THROW(ParseAdaptSummary(bad.dump(), "adapt.json"), InputError);
}

TEST(AdaptRecord, RefusesWhatItDidNotWrite) {
  const auto refused = [](const std::function<void(nlohmann::json&)>& edit, const char* what) {
    nlohmann::json j = Written();
    edit(j);
    try {
      ParseAdaptSummary(j.dump(), "a/adapt.json");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("a/adapt.json", 0), 0u) << e.what();
    }
  };
  refused([](nlohmann::json& j) { j.erase("adapted"); }, "adapted");
  refused([](nlohmann::json& j) { j["trials"] = "3"; }, "trials");
  refused([](nlohmann::json& j) { j["trials"] = 1e30; }, "trials");
  refused([](nlohmann::json& j) { j["elites"] = -4; }, "elites");
  refused([](nlohmann::json& j) { j["params"]["stop_fraction"] = 7; }, "stop_fraction");
  refused([](nlohmann::json& j) { j["time"] = "long"; }, "time");
  EXPECT_THROW(ParseAdaptSummary("[1, 2]", "a/adapt.json"), InputError);
}

}  // namespace
}  // namespace hexgait
