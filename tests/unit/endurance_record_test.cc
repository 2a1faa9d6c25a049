// endurance.json as a typed record: what `endurance` writes reads back field for field and
// dumps to the same text, a file without the later keys still reads, and a file that is no
// endurance.json is refused naming it.
#include "record/endurance_record.h"

#include <gtest/gtest.h>

#include <string>

#include "util/error.h"

namespace hexgait {
namespace {

EnduranceRecord ExampleEndurance() {
  EnduranceRecord r;
  r.test_time = 1000;
  r.dt = 0.0025;
  r.integrator = "euler";
  r.long_factor = 100;
  r.perturbed_factor = 10;
  r.push_impulse = 2;
  r.slope_degrees = 3;
  r.jitter = 0.05;
  r.trials = 4;
  r.step_factor = 0.5;
  r.seed = 18446744073709551615ull;
  r.random_wanted = 20;
  r.random_tried = 311;
  r.conditions = {{"none", "unperturbed", 100000, 1}, {"push", "push sideways", 10000, 4}};
  EnduranceGaitRecord fallen{"population 4, 10 generations", "seed-1/best.genome", {}};
  fallen.test.distance = 7.71 + 1e-15;
  fallen.test.fell = true;
  fallen.test.fall_time = 812.5;
  fallen.test.fall_cycle = 17;
  r.gaits = {fallen, {"random genomes that stood the test", "random 1", {}}};
  r.wall_seconds = 3.25;
  return r;
}

TEST(EnduranceRecord, ReadsBackWhatItWrites) {
  const EnduranceRecord r = ExampleEndurance();
  const std::string text = EnduranceRecordJson(r).dump(2) + "\n";
  const EnduranceRecord back = ParseEnduranceRecord(text, "endurance.json");
  EXPECT_EQ(back.seed, r.seed);
  EXPECT_EQ(back.random_tried, 311);
  ASSERT_EQ(back.conditions.size(), 2u);
  EXPECT_EQ(back.conditions[1].trials, 4);
  ASSERT_EQ(back.gaits.size(), 2u);
  EXPECT_EQ(back.gaits[0].test.distance, r.gaits[0].test.distance);  // bit for bit
  EXPECT_EQ(back.gaits[0].test.fall_cycle, 17);
  EXPECT_FALSE(back.gaits[1].test.fall_time.has_value());
  EXPECT_EQ(EnduranceRecordJson(back).dump(2) + "\n", text);
  EXPECT_EQ(EnduranceRecordJson(r)["hexgait_version"], HEXGAIT_VERSION);
  EXPECT_EQ(EnduranceRecordJson(r)["command"], "hexgait endurance");
  // A gait's test run is written as `simulate --json` writes a result.
  EXPECT_EQ(EnduranceRecordJson(r)["gaits"][1]["test"].dump(),
            R"({"distance":0.0,"diverged":false,"fall_cycle":null,"fall_time":null,)"
            R"("fell":false,"stopped_early":false})");
}

TEST(EnduranceRecord, ReadsAnOlderFileWithoutTheLaterKeys) {
  const EnduranceRecord r = ParseEnduranceRecord(
      R"({"command": "hexgait endurance", "test_time": 1000, "seed": 1,
          "conditions": [{"name": "none", "label": "unperturbed", "horizon": 1e5}],
          "gaits": [{"group": "g", "name": "best.genome",
                     "test": {"distance": 2.5, "fell": false, "fall_time": null,
                              "fall_cycle": null, "diverged": false}}]})",
      "old/endurance.json");
  EXPECT_EQ(r.hexgait_version, "");
  EXPECT_EQ(r.conditions.at(0).trials, 1);
  EXPECT_EQ(r.gaits.at(0).test.distance, 2.5);
  EXPECT_FALSE(r.gaits.at(0).test.stopped_early);
}

TEST(EnduranceRecord, RefusesAFileThatIsNotOneNamingIt) {
  try {
    ParseEnduranceRecord(R"({"gaits": [{"name": "x"}]})", "out/endurance/endurance.json");
    FAIL() << "accepted a gait without its test run";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out/endurance/endurance.json: not an endurance.json", 0),
              0u)
        << e.what();
  }
  EXPECT_THROW(ParseEnduranceRecord("[1, 2]", "x.json"), InputError);
}

// The seed is a JSON integer within 64 bits: nlohmann's value(key, uint64_t) cast 1e30 unchecked,
// undefined behaviour, which fuzzing the reader would reach; now it is refused by name.
TEST(EnduranceRecord, RefusesASeedThatIsNotA64BitInteger) {
  const nlohmann::json good = EnduranceRecordJson(ExampleEndurance());
  for (const nlohmann::json& seed :
       {nlohmann::json(1e30), nlohmann::json(-3), nlohmann::json(1.5), nlohmann::json("-1")}) {
    nlohmann::json j = good;
    j["seed"] = seed;
    try {
      ParseEnduranceRecord(j.dump(), "out/endurance/endurance.json");
      ADD_FAILURE() << "accepted the seed " << seed;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("out/endurance/endurance.json: ", 0), 0u) << e.what();
    }
  }
  nlohmann::json j = good;
  j["seed"] = 18446744073709551615ULL;
  EXPECT_EQ(ParseEnduranceRecord(j.dump(), "e.json").seed, 18446744073709551615ULL);
}

}  // namespace
}  // namespace hexgait
