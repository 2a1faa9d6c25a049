// The benchmark reports behind `hexgait bench speed|early-stop|scale`: their JSON keys (what
// docs and scripts read) and the scale measurement's JSON, written by rank 0 under mpirun and
// read back by the launching command.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bench/early_stop.h"
#include "bench/scale_measure.h"
#include "bench/speed.h"
#include "test_util.h"

namespace hexgait {
namespace {

TEST(BenchReport, ScaleMeasurementJsonRoundTrips) {
  ScaleMeasurement m;
  m.ranks = 3;
  m.threads_per_rank = 2;
  m.generations.push_back({0.25, 1.5, 0.125, 1.0, 0.75, 0.5, 12507});
  m.generations.push_back({0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 7});
  const ScaleMeasurement back =
      ScaleMeasurementFromJson(nlohmann::json::parse(ScaleMeasurementJson(m).dump()));
  EXPECT_EQ(back.ranks, 3);
  EXPECT_EQ(back.threads_per_rank, 2);
  ASSERT_EQ(back.generations.size(), 2u);
  EXPECT_EQ(back.generations[0].seconds_decode, 0.25);
  EXPECT_EQ(back.generations[0].seconds_evaluate, 1.5);
  EXPECT_EQ(back.generations[0].seconds_send, 0.125);
  EXPECT_EQ(back.generations[0].seconds_compute_max, 1.0);
  EXPECT_EQ(back.generations[0].seconds_compute_mean, 0.75);
  EXPECT_EQ(back.generations[0].seconds_communication, 0.5);
  EXPECT_EQ(back.generations[0].bytes, 12507);
  EXPECT_EQ(back.generations[1].bytes, 7);
  EXPECT_THROW(ScaleMeasurementFromJson(nlohmann::json::parse("{\"ranks\": 2}")),
               nlohmann::json::exception);
}

// Rows grouped by kind: the lane counts of each precision and the creature kernel's counts.
TEST(BenchReport, SpeedReportJsonGroupsRowsByKind) {
  SpeedReport r;
  r.rows = {{"naive", SpeedPathKind::kNaive, 1, 400, 410},
            {"single", SpeedPathKind::kScalar, 1, 300, 310},
            {"batched: 4 lanes", SpeedPathKind::kBatched, 4, 100, 110},
            {"batched: 8 lanes", SpeedPathKind::kBatched, 8, 50, 55},
            {"batched float: 8 lanes", SpeedPathKind::kBatchedFloat, 8, 40, 45}};
  r.naive = 0;
  r.single = 1;
  r.best = 3;
  r.best_float = 4;
  r.best_lanes = 8;
  r.best_lanes_float = 8;
  r.steps_per_evaluation = 400000;
  r.all_cores_ns = r.all_cores_float_ns = 25;
  r.peak_gflops = r.peak_gflops_float = 100;
  const nlohmann::json j = SpeedReportJson(r);
  EXPECT_EQ(j.at("ns_per_creature_step_by_lanes").size(), 2u);
  EXPECT_EQ(j.at("ns_per_creature_step_by_lanes").at("8").at("cpu").get<double>(), 50);
  EXPECT_EQ(j.at("ns_per_creature_step_by_lanes_float").size(), 1u);
  EXPECT_TRUE(j.at("ns_per_creature_step_creature_kernel").empty());
  EXPECT_EQ(j.at("speedup_batched_vs_naive").get<double>(), 8);
  EXPECT_EQ(j.at("ns_per_creature_step_batched_float_wall").get<double>(), 45);
  EXPECT_FALSE(j.contains("paper_experiment_seconds"));
  r.paper_experiment_timed = true;
  EXPECT_TRUE(SpeedReportJson(r).contains("paper_experiment_evaluations"));
}

TEST(BenchReport, EarlyStopOnAFewGenomes) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  EarlyStopSettings settings;
  settings.genomes = 4;
  settings.threads = 1;
  const EarlyStopReport r = MeasureEarlyStop(model, program, settings);
  EXPECT_EQ(r.genomes, 4);
  EXPECT_LE(r.stopped_early, r.fell);
  EXPECT_LE(r.crawl_runs, static_cast<size_t>(r.fell));
  EXPECT_GE(r.steps_saved_fraction, 0);
  const nlohmann::json j = EarlyStopReportJson(r);
  EXPECT_EQ(j.size(), 9u);
  EXPECT_EQ(j.at("genomes").get<int>(), 4);
}

}  // namespace
}  // namespace hexgait
