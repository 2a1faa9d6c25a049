#include "bench/scale_measure.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <numeric>

#include "eval/mpi_evaluator.h"
#include "ga/genome.h"
#include "ga/rng.h"
#include "motor/leg_targets.h"
#include "util/clock.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

// Random genes in the GA's range, a fresh stream per generation, as a GA's offspring would be.
std::vector<RestLengthTable> RandomTables(const CreatureModel& model, const MotorProgram& program,
                                          int population, uint64_t seed, int generation) {
  const auto layout = MakeGenomeLayout(model, program, false);
  const RestLengthTable geometric = GeometricRestLengths(model, program);
  Rng rng = Rng::ForStream(seed, static_cast<uint64_t>(generation));
  std::vector<RestLengthTable> tables;
  tables.reserve(static_cast<size_t>(population));
  Genome genome(layout);
  for (int i = 0; i < population; ++i) {
    for (int k = 0; k < genome.num_genes(); ++k) {
      genome.set_gene(k, static_cast<int>(rng.NextBelow(16)) - 8);
    }
    tables.push_back(PerturbedRestLengths(geometric, model, program, genome));
  }
  return tables;
}

}  // namespace

ScaleMeasurement MeasureScale(const CreatureModel& model, const MotorProgram& program,
                              const ScaleSettings& settings) {
  ScaleMeasurement m;
  m.ranks = MpiWorldSize();
  m.threads_per_rank = settings.evaluator.threads;
  MpiTimings timings;
  const std::unique_ptr<Evaluator> evaluator =
      m.ranks > 1 ? MakeMpiEvaluator(model, program, settings.evaluator, &timings)
                  : MakeLocalEvaluator(model, program, settings.evaluator);
  for (int g = 0; g < settings.generations; ++g) {
    ScaleGeneration s;
    auto start = Clock::now();
    const std::vector<RestLengthTable> tables =
        RandomTables(model, program, settings.population, settings.seed, g);
    s.seconds_decode = SecondsSince(start);
    start = Clock::now();
    evaluator->Evaluate(tables);
    s.seconds_evaluate = SecondsSince(start);
    if (m.ranks > 1) {
      s.seconds_send = timings.seconds_send;
      s.seconds_compute_max =
          *std::max_element(timings.seconds_compute.begin(), timings.seconds_compute.end());
      s.seconds_compute_mean =
          std::accumulate(timings.seconds_compute.begin(), timings.seconds_compute.end(), 0.0) /
          static_cast<double>(timings.seconds_compute.size());
      s.bytes = timings.bytes_sent + timings.bytes_received;
    } else {
      s.seconds_compute_max = s.seconds_compute_mean = s.seconds_evaluate;
    }
    s.seconds_communication = std::max(0.0, s.seconds_evaluate - s.seconds_compute_max);
    m.generations.push_back(s);
  }
  return m;
}

nlohmann::json ScaleMeasurementJson(const ScaleMeasurement& m) {
  nlohmann::json j;
  j["ranks"] = m.ranks;
  j["threads_per_rank"] = m.threads_per_rank;
  for (const ScaleGeneration& g : m.generations) {
    j["generations"].push_back({{"seconds_decode", g.seconds_decode},
                                {"seconds_evaluate", g.seconds_evaluate},
                                {"seconds_send", g.seconds_send},
                                {"seconds_compute_max", g.seconds_compute_max},
                                {"seconds_compute_mean", g.seconds_compute_mean},
                                {"seconds_communication", g.seconds_communication},
                                {"bytes", g.bytes}});
  }
  return j;
}

ScaleMeasurement ScaleMeasurementFromJson(const nlohmann::json& j) {
  ScaleMeasurement m;
  m.ranks = IntIn(j.at("ranks"), 0, std::numeric_limits<int>::max());
  m.threads_per_rank = IntIn(j.at("threads_per_rank"), 0, std::numeric_limits<int>::max());
  for (const auto& g : j.at("generations")) {
    ScaleGeneration s;
    s.seconds_decode = g.at("seconds_decode").get<double>();
    s.seconds_evaluate = g.at("seconds_evaluate").get<double>();
    s.seconds_send = g.at("seconds_send").get<double>();
    s.seconds_compute_max = g.at("seconds_compute_max").get<double>();
    s.seconds_compute_mean = g.at("seconds_compute_mean").get<double>();
    s.seconds_communication = g.at("seconds_communication").get<double>();
    s.bytes = IntegerIn(g.at("bytes"), 0, std::numeric_limits<long long>::max());
    m.generations.push_back(s);
  }
  return m;
}

}  // namespace hexgait
