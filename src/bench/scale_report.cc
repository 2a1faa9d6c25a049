#include "bench/scale_report.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "bench/cpu_model.h"
#include "eval/evaluator.h"
#include "motor/leg_targets.h"
#include "simd/isa.h"
#include "util/median.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

ScaleRow Summarise(const ScaleMeasurement& m) {
  ScaleRow r;
  r.ranks = m.ranks;
  r.threads = m.threads_per_rank;
  auto median = [&](double ScaleGeneration::*field) {
    std::vector<double> v;
    for (const ScaleGeneration& g : m.generations) v.push_back(g.*field);
    return Median(v, 0);
  };
  r.evaluate = median(&ScaleGeneration::seconds_evaluate);
  r.compute_max = median(&ScaleGeneration::seconds_compute_max);
  r.compute_mean = median(&ScaleGeneration::seconds_compute_mean);
  r.communication = median(&ScaleGeneration::seconds_communication);
  r.send = median(&ScaleGeneration::seconds_send);
  r.decode = median(&ScaleGeneration::seconds_decode);
  std::vector<double> bytes;
  for (const ScaleGeneration& g : m.generations) bytes.push_back(static_cast<double>(g.bytes));
  r.bytes = Median(bytes, 0);
  return r;
}

// The model's inputs from this machine's measurements: per-evaluation compute on one core
// from the one-rank row, scaled to model_time; rank 0's decoding and the bytes per
// evaluation from a multi-rank row, or from the one-rank row and the table and result sizes
// when none ran.
ClusterModel ModelFrom(const ScaleBenchSettings& settings, const std::vector<ScaleRow>& rows,
                       int cores, double table_bytes) {
  const ScaleRow& one = rows.front();
  const double population = settings.measure.population;
  ClusterModel m;
  m.cores_per_rank = settings.model_cores;
  m.lanes = NativeBatchLanes(BatchIsa::kAuto, settings.measure.evaluator.precision);
  const double used = std::min(one.threads, cores);
  m.seconds_per_eval = one.compute_max * used / population * (settings.model_time / settings.time);
  m.serial_seconds_per_eval = one.decode / population;
  m.bytes_per_eval = table_bytes;
  for (const ScaleRow& r : rows) {
    if (r.ranks > 1 && r.bytes > 0) {
      m.bytes_per_eval = r.bytes / (population * (r.ranks - 1.0) / r.ranks);
      // Rank 0's own work as it runs under mpirun, as on a cluster. (Under OpenMPI the freed
      // tables of one generation are reused by the next; a plain process returns them to the
      // system and page-faults them back, several times slower.)
      m.serial_seconds_per_eval = r.decode / population;
    }
  }
  m.latency_seconds = settings.latency_us * 1e-6;
  m.bytes_per_second = settings.bandwidth_gbs * 1e9;
  return m;
}

// The smallest power-of-two population that reaches `target` efficiency on `ranks` ranks.
long long PopulationFor(const ClusterModel& m, int ranks, double target) {
  for (long long p = 1; p <= (1LL << 30); p *= 2) {
    if (PredictGeneration(m, p, ranks).efficiency >= target) return p;
  }
  return -1;
}

}  // namespace

ScaleReport MeasureScaleAcrossRanks(const CreatureModel& model, const MotorProgram& program,
                                    const ScaleBenchSettings& settings,
                                    const std::function<ScaleMeasurement(int ranks)>& on_ranks,
                                    const LogLine& note) {
  const int population = settings.measure.population;
  const int generations = settings.measure.generations;
  ScaleReport report;
  report.cpu = CpuModel();
  report.cores = ResolveThreadCount(0);
  report.mpi = static_cast<bool>(on_ranks);
  report.population = population;
  report.generations = generations;
  report.time_units = settings.time;
  report.precision = PrecisionName(settings.measure.evaluator.precision);

  std::vector<int> counts = settings.ranks;
  if (counts.empty() || counts.front() != 1) counts.insert(counts.begin(), 1);  // the baseline
  for (const int ranks : counts) {
    if (StopRequested()) throw Stopped("bench scale stopped; nothing written");
    if (ranks > 1 && !on_ranks) {
      report.skipped.push_back(ranks);
      continue;
    }
    if (note) {
      note("scale: " + std::to_string(ranks) + " rank" + (ranks > 1 ? "s" : "") + ", population " +
           std::to_string(population) + ", " + std::to_string(generations) + " generations");
    }
    report.rows.push_back(
        Summarise(ranks == 1 ? MeasureScale(model, program, settings.measure) : on_ranks(ranks)));
  }
  for (ScaleRow& r : report.rows) {
    r.evaluations_per_second = population / r.evaluate;
    r.seconds_generation = r.evaluate + r.decode;
    r.speedup = report.rows.front().evaluate / r.evaluate;
    r.oversubscribed = r.ranks * r.threads > report.cores;
  }

  const RestLengthTable& example = GeometricRestLengths(model, program);
  const double table_bytes =
      static_cast<double>(example.length.size() * sizeof(double)) + sizeof(RunResult);
  report.model = ModelFrom(settings, report.rows, report.cores, table_bytes);
  report.model_time = settings.model_time;
  report.latency_us = settings.latency_us;
  report.bandwidth_gbs = settings.bandwidth_gbs;
  report.cluster_ranks = settings.model_ranks;
  report.model_evaluations = settings.model_evaluations;
  report.cluster_populations = {64, 256, 1024, 4096, 16384, 65536};
  for (const int n : report.cluster_ranks) {
    for (const long long p : report.cluster_populations) {
      ScalePrediction prediction{n, p, PredictGeneration(report.model, p, n)};
      const long long search_generations = (settings.model_evaluations + p - 1) / p;
      prediction.seconds_search =
          static_cast<double>(search_generations) * prediction.time.seconds_total;
      report.predicted.push_back(prediction);
    }
    report.population_for_90_percent.push_back(PopulationFor(report.model, n, 0.9));
  }
  return report;
}

nlohmann::json ScaleReportJson(const ScaleReport& r) {
  nlohmann::json j;
  j["cpu"] = r.cpu;
  j["cores"] = r.cores;
  j["mpi"] = r.mpi;
  j["population"] = r.population;
  j["time_units"] = r.time_units;
  j["precision"] = r.precision;
  for (const ScaleRow& row : r.rows) {
    j["measured"].push_back({{"ranks", row.ranks},
                             {"threads_per_rank", row.threads},
                             {"oversubscribed", row.oversubscribed},
                             {"evaluations_per_second", row.evaluations_per_second},
                             {"seconds_generation", row.seconds_generation},
                             {"seconds_compute", row.compute_max},
                             {"seconds_compute_mean", row.compute_mean},
                             {"seconds_communication", row.communication},
                             {"seconds_send", row.send},
                             {"seconds_decode", row.decode},
                             {"bytes_per_generation", row.bytes}});
  }
  const ClusterModel& m = r.model;
  j["model"] = {{"cores_per_rank", m.cores_per_rank},
                {"lanes", m.lanes},
                {"seconds_per_eval_core", m.seconds_per_eval},
                {"serial_seconds_per_eval", m.serial_seconds_per_eval},
                {"bytes_per_eval", m.bytes_per_eval},
                {"latency_seconds", m.latency_seconds},
                {"bytes_per_second", m.bytes_per_second},
                {"time_units", r.model_time}};
  j["model"]["evaluations"] = r.model_evaluations;
  for (size_t k = 0; k < r.cluster_ranks.size(); ++k) {
    for (const ScalePrediction& p : r.predicted) {
      if (p.ranks != r.cluster_ranks[k]) continue;
      j["predicted"].push_back({{"ranks", p.ranks},
                                {"population", p.population},
                                {"seconds_generation", p.time.seconds_total},
                                {"seconds_compute", p.time.seconds_compute},
                                {"seconds_communication", p.time.seconds_communication},
                                {"seconds_serial", p.time.seconds_serial},
                                {"efficiency", p.time.efficiency},
                                {"seconds_search", p.seconds_search}});
    }
    j["population_for_90_percent"][std::to_string(r.cluster_ranks[k])] =
        r.population_for_90_percent[k];
  }
  return j;
}

}  // namespace hexgait
