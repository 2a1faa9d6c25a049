// hexgait bench scale: evaluations per second for one large population on 1, 2, 4... MPI ranks
// of this machine and the cluster model of docs/scaling.md fed with them (bench/scale_report.h
// measures; this prints). Each rank count other than 1 runs as `mpirun -np N hexgait bench
// scale ...`, whose rank 0 measures and prints JSON: launching this binary again is the
// command's part.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench_common.h"
#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "bench/scale_report.h"
#include "eval/mpi_evaluator.h"
#include "run/work_size.h"
#include "util/child_process.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct ScaleOptions {
  SceneOptions scene;
  std::string ranks = "1,2,4";
  int population = 1024;
  int generations = 3;
  double time = 100;
  int threads = 0;
  std::string precision = "double";
  uint64_t seed = 1;
  std::string mpirun = "mpirun";
  bool json = false;
  // The cluster the model predicts for.
  int model_cores = 16;
  double model_time = 1000;
  double latency_us = 2;
  double bandwidth_gbs = 10;
  std::string model_ranks = "64,1024";
  long long model_evaluations = 0;
};

// A comma-separated list of distinct rank counts in [1, most], in the order given; `option`
// and `example` name them in the error.
std::vector<int> ParseRankList(const std::string& text, const char* option, long most,
                               const char* example) {
  std::vector<int> ranks;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || n < 1 || n > most) {
      throw InputError(std::string(option) + " '" + text + "': expected rank counts from 1 to " +
                       std::to_string(most) + ", like " + example);
    }
    if (std::find(ranks.begin(), ranks.end(), n) == ranks.end()) {
      ranks.push_back(static_cast<int>(n));
    }
  }
  if (ranks.empty()) throw InputError(std::string(option) + " '" + text + "': no rank count");
  return ranks;
}

// Measured rank counts, ascending.
std::vector<int> ParseRanks(const std::string& text) {
  std::vector<int> ranks = ParseRankList(text, "--ranks", 64, "1,2,4");
  std::sort(ranks.begin(), ranks.end());
  return ranks;
}

int HardwareThreads() {
  return ResolveThreadCount(0);
}

// Threads for each rank: as asked, else this machine's cores shared by the ranks on it.
int ThreadsPerRank(int requested, int ranks_here) {
  if (requested > 0) return requested;
  return std::max(1, HardwareThreads() / std::max(1, ranks_here));
}

int RanksOnThisMachine() {
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  return local ? std::max(1, std::atoi(local)) : MpiWorldSize();
}

ScaleBenchSettings MakeSettings(const ScaleOptions& opt) {
  ScaleBenchSettings s;
  s.ranks = ParseRanks(opt.ranks);  // first: its message comes before the scene's
  s.measure.evaluator.run = MakeRunOptions(opt.scene, opt.time);
  s.measure.evaluator.threads = ThreadsPerRank(opt.threads, RanksOnThisMachine());
  s.measure.evaluator.precision = ParsePrecision(opt.precision);
  s.measure.population = opt.population;
  s.measure.generations = opt.generations;
  s.measure.seed = opt.seed;
  s.time = opt.time;
  s.model_cores = opt.model_cores;
  s.model_time = opt.model_time;
  s.latency_us = opt.latency_us;
  s.bandwidth_gbs = opt.bandwidth_gbs;
  s.model_ranks = ParseRankList(opt.model_ranks, "--model-ranks", 1000000, "16,64,1024");
  s.model_evaluations = opt.model_evaluations;
  return s;
}

std::vector<std::string> ChildArgs(const ScaleOptions& opt, int ranks) {
  // Unbound: a rank runs several threads, and OpenMPI would bind each rank to one core.
  std::vector<std::string> args = {opt.mpirun, "--oversubscribe",    "--bind-to", "none",
                                   "-np",      std::to_string(ranks)};
  if (geteuid() == 0) args.insert(args.begin() + 1, "--allow-run-as-root");
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  for (const std::string& a :
       {exe, std::string("bench"), std::string("scale"), std::string("--population"),
        std::to_string(opt.population), std::string("--generations"),
        std::to_string(opt.generations), std::string("--time"), std::to_string(opt.time),
        std::string("--threads"), std::to_string(opt.threads), std::string("--precision"),
        opt.precision, std::string("--seed"), std::to_string(opt.seed), std::string("--dt"),
        std::to_string(opt.scene.dt), std::string("--integrator"), opt.scene.integrator}) {
    args.push_back(a);
  }
  if (!opt.scene.creature_path.empty())
    args.insert(args.end(), {"--creature", opt.scene.creature_path});
  if (!opt.scene.motor_path.empty()) args.insert(args.end(), {"--motor", opt.scene.motor_path});
  if (!opt.scene.damage.empty()) args.insert(args.end(), {"--damage", opt.scene.damage});
  if (opt.scene.allow_long) args.push_back("--allow-long");
  return args;
}

// `ranks` ranks' measurement: this binary again under mpirun, whose rank 0 prints it.
ScaleMeasurement MeasureWithMpirun(const ScaleOptions& opt, int ranks) {
  ChildProcess child(ChildArgs(opt, ranks), false, ChildProcess::Stdout::kCapture, true);
  const std::string output = child.ReadOutput();
  const int status = child.Wait();
  if (status != 0) {
    throw InputError("'" + opt.mpirun + " -np " + std::to_string(ranks) +
                     " hexgait bench scale' failed with status " + std::to_string(status));
  }
  try {
    return ScaleMeasurementFromJson(nlohmann::json::parse(output));
  } catch (const nlohmann::json::exception&) {
    throw InputError("'" + opt.mpirun + " -np " + std::to_string(ranks) +
                     " hexgait bench scale' printed no measurement");
  }
}

bool HaveMpirun(const std::string& mpirun) {
  try {
    ChildProcess probe({mpirun, "--version"}, false);
    return probe.Wait() == 0;
  } catch (const InputError&) {
    return false;
  }
}

void PrintTable(const ScaleOptions& opt, const ScaleReport& r) {
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

void Run(const ScaleOptions& opt) {
  if (opt.population < 1 || opt.population > 1000000) {
    throw InputError("--population must be in [1, 1000000]");
  }
  if (opt.generations < 1 || opt.generations > 100) {
    throw InputError("--generations must be in [1, 100]");
  }
  if (opt.threads < 0 || opt.threads > 1024) throw InputError("--threads must be in [0, 1024]");
  if (opt.model_evaluations < 0 || opt.model_evaluations > 1000000000000LL) {
    throw InputError("--model-evaluations must be in [0, 1e12]");
  }
  if (opt.model_cores < 1 || opt.model_cores > 4096) {
    throw InputError("--model-cores must be in [1, 4096]");
  }
  if (!(opt.model_time > 0 && opt.model_time <= 1e6)) {
    throw InputError("--model-time must be in (0, 1e6]");
  }
  if (!(opt.latency_us >= 0 && opt.latency_us <= 1e6)) {
    throw InputError("--latency-us must be in [0, 1e6]");
  }
  if (!(opt.bandwidth_gbs > 0 && opt.bandwidth_gbs <= 1e4)) {
    throw InputError("--bandwidth-gbs must be in (0, 1e4]");
  }
  if (ParsePrecision(opt.precision) == Precision::kFloat && opt.scene.integrator != "euler") {
    throw InputError("--precision float needs --integrator euler");
  }
  const ScaleBenchSettings settings = MakeSettings(opt);
  const double evaluations = static_cast<double>(opt.population) * opt.generations *
                             static_cast<double>(settings.ranks.size() + 1);
  const Scene scene = LoadScene(opt.scene);
  RefuseLongRun("--population " + std::to_string(opt.population) + " x --generations " +
                    std::to_string(opt.generations) + " for each of --ranks " + opt.ranks,
                EstimatedSimulationSeconds(scene.model, evaluations, opt.time / opt.scene.dt,
                                           StepPath::kBatched, HardwareThreads()),
                opt.scene.allow_long);

  if (MpiWorldSize() > 1) {  // launched by the command below, through mpirun
    // The worker ranks serve MeasureScale's evaluator and end there.
    const ScaleMeasurement m = MeasureScale(scene.model, scene.program, settings.measure);
    std::printf("%s\n", ScaleMeasurementJson(m).dump().c_str());
    return;
  }

  std::function<ScaleMeasurement(int)> on_ranks;
  if (MpiBuiltIn() && HaveMpirun(opt.mpirun)) {
    on_ranks = [&opt](int ranks) { return MeasureWithMpirun(opt, ranks); };
  }
  const ScaleReport report =
      MeasureScaleAcrossRanks(scene.model, scene.program, settings, on_ranks, PrintProgressLine);
  if (opt.json) {
    std::printf("%s\n", ScaleReportJson(report).dump(2).c_str());
  } else {
    PrintTable(opt, report);
  }
}

}  // namespace

void AddBenchScale(CLI::App& bench) {
  auto opt = std::make_shared<ScaleOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "scale",
      "Evaluations per second on 1, 2, 4... MPI ranks (compute against communication), and "
      "the cluster model of docs/scaling.md fed with them");
  cmd->add_option("--ranks", opt->ranks, "Rank counts to measure (1 is always measured)")
      ->capture_default_str();
  cmd->add_option("--population", opt->population, "Creatures per generation")
      ->capture_default_str();
  cmd->add_option("--generations", opt->generations, "Generations measured (the median is shown)")
      ->capture_default_str();
  cmd->add_option("--time", opt->time, "Simulated time per evaluation (time units)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->threads,
                  "Threads per rank (0: this machine's cores shared by its ranks)")
      ->capture_default_str();
  AddPrecisionOption(cmd, opt->precision, "double or float");
  AddSeedOption(cmd, opt->seed, "Seed of the random genomes");
  cmd->add_option("--mpirun", opt->mpirun, "The MPI launcher")->capture_default_str();
  cmd->add_option("--model-cores", opt->model_cores, "Model: cores per rank on the cluster")
      ->capture_default_str();
  cmd->add_option("--model-time", opt->model_time,
                  "Model: simulated time per evaluation (1000 is the paper's)")
      ->capture_default_str();
  cmd->add_option("--latency-us", opt->latency_us, "Model: latency per message (microseconds)")
      ->capture_default_str();
  cmd->add_option("--bandwidth-gbs", opt->bandwidth_gbs,
                  "Model: rank 0's link bandwidth (gigabytes per second)")
      ->capture_default_str();
  cmd->add_option("--model-ranks", opt->model_ranks, "Model: rank counts to predict for")
      ->capture_default_str();
  cmd->add_option("--model-evaluations", opt->model_evaluations,
                  "Model: also predict a whole search of this many evaluations, in generations "
                  "(or repertoire batches) of each population (0: no)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text");
  AddSceneOptions(cmd, opt->scene);
  Distributed(cmd);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
