// run.json as a typed record: what evolve writes reads back field for field, a file from before
// the "algorithm" key is the paper's GA, and a damaged one is refused naming the file.
#include "record/run_record.h"

#include <gtest/gtest.h>

#include <string>

#include "util/error.h"

namespace hexgait {
namespace {

RunRecord Example(const std::string& algorithm) {
  RunRecord r;
  r.algorithm = algorithm;
  r.seed = 18446744073709551615ull;  // every bit of a 64-bit seed
  r.population = 18;
  r.generations = 3;
  // Each optimizer's own settings (its table's), written beside the other members.
  if (algorithm == "ga") {
    r.settings = {{"crossover_rate", 0.7},
                  {"mutation_rate", 0.01},
                  {"initial_mutation_rate", 0.02},
                  {"elites", 1}};
    r.chromosome_bits = 480;
  } else {
    r.settings = {{"sigma", 2.5}};
  }
  r.genes = 120;
  r.time = 1000;
  r.dt = 0.0025;
  r.integrator = "euler";
  r.precision = "double";
  r.evaluations = 72;
  r.unoptimized.distance = 1.2617;
  r.unoptimized.fell = true;
  r.unoptimized.fall_time = 156.25;
  r.unoptimized.fall_cycle = 3;
  r.best.distance = r.best_fitness = 7.71 + 1e-15;
  r.history = {{0, 3.5, 2.25, 1.0, 0, 18, 0.5, 0}, {1, 7.71 + 1e-15, 4.0, -0.5, 2, 18, 0.5, 3}};
  return r;
}

TEST(RunRecord, ReadsBackWhatItWrites) {
  for (const std::string algorithm : {"ga", "cmaes"}) {
    const RunRecord r = Example(algorithm);
    const RunRecord back = ParseRunRecord(RunRecordJson(r).dump(2), "run.json");
    EXPECT_EQ(back.algorithm, algorithm);
    EXPECT_EQ(back.seed, r.seed);
    EXPECT_EQ(back.population, 18);
    EXPECT_EQ(back.best_fitness, r.best_fitness);  // bit for bit
    EXPECT_EQ(back.unoptimized.fall_cycle, 3);
    EXPECT_EQ(back.unoptimized.fall_time, 156.25);
    EXPECT_FALSE(back.best.fall_cycle.has_value());
    ASSERT_EQ(back.history.size(), 2u);
    EXPECT_EQ(back.history[1].best, r.history[1].best);
    EXPECT_EQ(back.history[1].diverged, 3);
    EXPECT_EQ(back.ratio(), r.best_fitness / 1.2617);
    EXPECT_EQ(RunRecordJson(back), RunRecordJson(r));
    EXPECT_EQ(back.settings, r.settings);
    if (algorithm == "ga") {
      EXPECT_EQ(RunRecordJson(r).at("elites"), 1);
      EXPECT_FALSE(RunRecordJson(r).contains("algorithm"));  // the GA's files stay as they were
    } else {
      EXPECT_EQ(RunRecordJson(r).at("sigma"), 2.5);
      EXPECT_FALSE(RunRecordJson(r).contains("crossover_rate"));
      EXPECT_FALSE(RunRecordJson(r).contains("chromosome_bits"));
    }
  }
}

TEST(RunRecord, RefusesAFileWithoutItsFieldsNamingIt) {
  nlohmann::json j = RunRecordJson(Example("ga"));
  j.erase("evaluations");
  try {
    ParseRunRecord(j.dump(), "out/run/run.json");
    FAIL() << "accepted a run.json without evaluations";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out/run/run.json: not a run.json written by hexgait "
                                          "evolve",
                                          0),
              0u)
        << e.what();
  }
  EXPECT_THROW(ParseRunRecord("[1, 2]", "x.json"), InputError);
}

// nlohmann's get<int>() casts a float unchecked (1e24 is undefined behaviour); the fuzzer found
// it. Every integer field must be a JSON integer in range, or the file is refused by name.
TEST(RunRecord, RefusesAnIntegerFieldThatIsAFractionOrOutOfRange) {
  const std::vector<std::pair<std::string, nlohmann::json>> bad = {{"population", 1.55556e+24},
                                                                   {"population", 2.5},
                                                                   {"population", -4},
                                                                   {"generations", 1e300},
                                                                   {"evaluations", 3000000000LL},
                                                                   {"seed", -3},
                                                                   {"seed", 1.0},
                                                                   {"elites", "1"}};
  for (const auto& [key, value] : bad) {
    nlohmann::json j = RunRecordJson(Example("ga"));
    j[key] = value;
    EXPECT_THROW(ParseRunRecord(j.dump(), "run.json"), InputError) << key << " = " << value;
  }
  nlohmann::json j = RunRecordJson(Example("ga"));
  j["unoptimized"]["fell"] = true;
  j["unoptimized"]["fall_cycle"] = 1e30;
  EXPECT_THROW(ParseRunRecord(j.dump(), "run.json"), InputError);
  j["history"][0]["diverged"] = 0.5;
  EXPECT_THROW(ParseRunRecord(j.dump(), "run.json"), InputError);
}

}  // namespace
}  // namespace hexgait
