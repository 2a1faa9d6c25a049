// hexgait bench scale: evaluations per second for one large population on 1, 2, 4... MPI ranks
// and the cluster model of docs/scaling.md fed with them (MeasureScaling, run/bench_request.h,
// measures and launches the other rank counts; this prints).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/bench_common.h"
#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "eval/mpi_evaluator.h"
#include "run/bench_request.h"

namespace hexgait {
namespace {

struct ScaleFlags {
  ScaleRequest request;
  bool json = false;
};

void PrintTable(const ScaleRequest& opt, const ScaleReport& r) {
  std::printf(
      "bench scale: %s, %d hardware threads; population %d, %g time units per "
      "evaluation, %s, median of %d generations\n",
      r.cpu.c_str(), r.cores, r.population, r.time_units, r.precision.c_str(), r.generations);
  if (!r.skipped.empty()) {
    std::printf("not measured: %s ranks (%s)\n", opt.ranks.c_str(),
                MpiBuiltIn() ? "no mpirun in PATH" : "this hexgait was built without MPI");
  }
  std::printf("\n%5s %7s %10s %11s %9s %9s %9s %9s %8s\n", "ranks", "threads", "evals/s", "s/gen",
              "compute", "comm", "decode", "MB/gen", "speedup");
  for (const ScaleRow& row : r.rows) {
    std::printf("%5d %7d %10.1f %11.3f %9.3f %9.3f %9.4f %9.2f %7.2fx%s\n", row.ranks, row.threads,
                row.evaluations_per_second, row.seconds_generation, row.compute_max,
                row.communication, row.decode, row.bytes / 1e6, row.speedup,
                row.oversubscribed ? "  (oversubscribed)" : "");
  }
  std::printf(
      "\ncompute: the slowest rank's evaluation; comm: the rest of the Evaluate call (sends, "
      "receives, waiting); decode: rank 0 making the genomes and their tables.\n");
  const ClusterModel& m = r.model;
  std::printf(
      "\nmodel (docs/scaling.md): %d cores x %d lanes per rank, %.3g s per evaluation per core "
      "at %g time units, %.3g s serial and %.0f bytes per evaluation, latency %g us, %g GB/s\n",
      m.cores_per_rank, m.lanes, m.seconds_per_eval, r.model_time, m.serial_seconds_per_eval,
      m.bytes_per_eval, r.latency_us, r.bandwidth_gbs);
  std::printf("%10s", "population");
  for (const int n : r.cluster_ranks) std::printf("   %4d ranks: s/gen  efficiency", n);
  std::printf("\n");
  for (const long long p : r.cluster_populations) {
    std::printf("%10lld", p);
    for (const int n : r.cluster_ranks) {
      for (const ScalePrediction& t : r.predicted) {
        if (t.ranks == n && t.population == p) {
          std::printf("   %17.3f  %9.1f%%", t.time.seconds_total, 100 * t.time.efficiency);
        }
      }
    }
    std::printf("\n");
  }
  for (size_t k = 0; k < r.cluster_ranks.size(); ++k) {
    std::printf("population for 90%% efficiency on %d ranks: %lld\n", r.cluster_ranks[k],
                r.population_for_90_percent[k]);
  }
  if (r.model_evaluations > 0) {
    std::printf("\n%lld evaluations of %g time units, in generations of each population:\n",
                r.model_evaluations, r.model_time);
    std::printf("%10s", "population");
    for (const int n : r.cluster_ranks) std::printf("   %4d ranks: hours", n);
    std::printf("\n");
    for (const long long p : r.cluster_populations) {
      std::printf("%10lld", p);
      for (const int n : r.cluster_ranks) {
        for (const ScalePrediction& t : r.predicted) {
          if (t.ranks == n && t.population == p) std::printf("   %17.2f", t.seconds_search / 3600);
        }
      }
      std::printf("\n");
    }
  }
}

void Run(const ScaleRequest& request, bool json) {
  const ScaleResult result = MeasureScaling(request, PrintProgressLine);
  if (result.measured_alone) {  // launched by MeasureScaling under mpirun: rank 0's JSON
    std::printf("%s\n", ScaleMeasurementJson(result.measurement).dump().c_str());
  } else if (json) {
    std::printf("%s\n", ScaleReportJson(result.report).dump(2).c_str());
  } else {
    PrintTable(request, result.report);
  }
}

}  // namespace

void AddBenchScale(CLI::App& bench) {
  auto opt = std::make_shared<ScaleFlags>();
  CLI::App* cmd = bench.add_subcommand(
      "scale",
      "Evaluations per second on 1, 2, 4... MPI ranks (compute against communication), and "
      "the cluster model of docs/scaling.md fed with them");
  cmd->add_option("--ranks", opt->request.ranks, "Rank counts to measure (1 is always measured)")
      ->capture_default_str();
  cmd->add_option("--population", opt->request.population, "Creatures per generation")
      ->capture_default_str();
  cmd->add_option("--generations", opt->request.generations,
                  "Generations measured (the median is shown)")
      ->capture_default_str();
  cmd->add_option("--time", opt->request.time, "Simulated time per evaluation (time units)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->request.threads,
                  "Threads per rank (0: this machine's cores shared by its ranks)")
      ->capture_default_str();
  AddPrecisionOption(cmd, opt->request.precision, "double or float");
  AddSeedOption(cmd, opt->request.seed, "Seed of the random genomes");
  cmd->add_option("--mpirun", opt->request.mpirun, "The MPI launcher")->capture_default_str();
  cmd->add_option("--model-cores", opt->request.model_cores, "Model: cores per rank on the cluster")
      ->capture_default_str();
  cmd->add_option("--model-time", opt->request.model_time,
                  "Model: simulated time per evaluation (1000 is the paper's)")
      ->capture_default_str();
  cmd->add_option("--latency-us", opt->request.latency_us,
                  "Model: latency per message (microseconds)")
      ->capture_default_str();
  cmd->add_option("--bandwidth-gbs", opt->request.bandwidth_gbs,
                  "Model: rank 0's link bandwidth (gigabytes per second)")
      ->capture_default_str();
  cmd->add_option("--model-ranks", opt->request.model_ranks, "Model: rank counts to predict for")
      ->capture_default_str();
  cmd->add_option("--model-evaluations", opt->request.model_evaluations,
                  "Model: also predict a whole search of this many evaluations, in generations "
                  "(or repertoire batches) of each population (0: no)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text");
  AddSceneOptions(cmd, opt->request.scene);
  Distributed(cmd);
  cmd->callback([opt] { Run(opt->request, opt->json); });
}

}  // namespace hexgait
