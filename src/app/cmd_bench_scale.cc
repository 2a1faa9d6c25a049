// hexgait bench scale: evaluations per second for one large population on 1, 2, 4... MPI ranks
// of this machine, each generation's time split into compute and communication, and the
// cluster model of docs/scaling.md fed with those measurements. Each rank count other than 1
// runs as `mpirun -np N hexgait bench scale ...`, whose rank 0 measures and prints JSON.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/bench_common.h"
#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "run/work_size.h"
#include "bench/scale_measure.h"
#include "bench/scale_model.h"
#include "eval/mpi_evaluator.h"
#include "simd/isa.h"
#include "util/child_process.h"
#include "util/error.h"
#include "util/median.h"
#include "util/stop_signal.h"

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
};

std::vector<int> ParseRanks(const std::string& text) {
  std::vector<int> ranks;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || n < 1 || n > 64) {
      throw InputError("--ranks '" + text + "': expected rank counts from 1 to 64, like 1,2,4");
    }
    if (std::find(ranks.begin(), ranks.end(), n) == ranks.end()) {
      ranks.push_back(static_cast<int>(n));
    }
  }
  if (ranks.empty()) throw InputError("--ranks '" + text + "': no rank count");
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

ScaleSettings MakeSettings(const ScaleOptions& opt) {
  ScaleSettings s;
  s.evaluator.run = MakeRunOptions(opt.scene, opt.time);
  s.evaluator.threads = ThreadsPerRank(opt.threads, RanksOnThisMachine());
  s.evaluator.precision = ParsePrecision(opt.precision);
  s.population = opt.population;
  s.generations = opt.generations;
  s.seed = opt.seed;
  return s;
}

nlohmann::json MeasurementJson(const ScaleMeasurement& m, int threads) {
  nlohmann::json j;
  j["ranks"] = m.ranks;
  j["threads_per_rank"] = threads;
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

// One rank count's medians over its generations.
struct Row {
  int ranks = 1, threads = 1;
  double evaluate = 0, compute_max = 0, compute_mean = 0, communication = 0, send = 0, decode = 0,
         bytes = 0;
};

Row Summarise(const nlohmann::json& j) {
  Row r;
  r.ranks = j.at("ranks").get<int>();
  r.threads = j.at("threads_per_rank").get<int>();
  auto median = [&](const char* key) {
    std::vector<double> v;
    for (const auto& g : j.at("generations")) v.push_back(g.at(key).get<double>());
    return Median(v, 0);
  };
  r.evaluate = median("seconds_evaluate");
  r.compute_max = median("seconds_compute_max");
  r.compute_mean = median("seconds_compute_mean");
  r.communication = median("seconds_communication");
  r.send = median("seconds_send");
  r.decode = median("seconds_decode");
  r.bytes = median("bytes");
  return r;
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
  if (opt.scene.allow_long) args.push_back("--allow-long");
  return args;
}

nlohmann::json MeasureWithMpirun(const ScaleOptions& opt, int ranks) {
  ChildProcess child(ChildArgs(opt, ranks), false, ChildProcess::Stdout::kCapture, true);
  const std::string output = child.ReadOutput();
  const int status = child.Wait();
  if (status != 0) {
    throw InputError("'" + opt.mpirun + " -np " + std::to_string(ranks) +
                     " hexgait bench scale' failed with status " + std::to_string(status));
  }
  try {
    return nlohmann::json::parse(output);
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

// The model's inputs from this machine's measurements: per-evaluation compute on one core
// from the one-rank row, scaled to --model-time; rank 0's decoding and the bytes per
// evaluation from a multi-rank row, or from the one-rank row and the table and result sizes
// when none ran.
ClusterModel ModelFrom(const ScaleOptions& opt, const Row& one, const std::vector<Row>& rows,
                       const ScaleSettings& settings, double table_bytes) {
  ClusterModel m;
  m.cores_per_rank = opt.model_cores;
  m.lanes = NativeBatchLanes(BatchIsa::kAuto, settings.evaluator.precision);
  const double cores = std::min(one.threads, HardwareThreads());
  m.seconds_per_eval = one.compute_max * cores / opt.population * (opt.model_time / opt.time);
  m.serial_seconds_per_eval = one.decode / opt.population;
  m.bytes_per_eval = table_bytes;
  for (const Row& r : rows) {
    if (r.ranks > 1 && r.bytes > 0) {
      m.bytes_per_eval = r.bytes / (opt.population * (r.ranks - 1.0) / r.ranks);
      // Rank 0's own work as it runs under mpirun, as on a cluster. (Under OpenMPI the freed
      // tables of one generation are reused by the next; a plain process returns them to the
      // system and page-faults them back, several times slower.)
      m.serial_seconds_per_eval = r.decode / opt.population;
    }
  }
  m.latency_seconds = opt.latency_us * 1e-6;
  m.bytes_per_second = opt.bandwidth_gbs * 1e9;
  return m;
}

// The smallest power-of-two population that reaches `target` efficiency on `ranks` ranks.
long long PopulationFor(const ClusterModel& m, int ranks, double target) {
  for (long long p = 1; p <= (1LL << 30); p *= 2) {
    if (PredictGeneration(m, p, ranks).efficiency >= target) return p;
  }
  return -1;
}

void Run(const ScaleOptions& opt) {
  if (opt.population < 1 || opt.population > 1000000) {
    throw InputError("--population must be in [1, 1000000]");
  }
  if (opt.generations < 1 || opt.generations > 100) {
    throw InputError("--generations must be in [1, 100]");
  }
  if (opt.threads < 0 || opt.threads > 1024) throw InputError("--threads must be in [0, 1024]");
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
  const std::vector<int> rank_counts = ParseRanks(opt.ranks);
  const ScaleSettings settings = MakeSettings(opt);
  const double evaluations = static_cast<double>(opt.population) * opt.generations *
                             static_cast<double>(rank_counts.size() + 1);
  RefuseLongRun(
      "--population " + std::to_string(opt.population) + " x --generations " +
          std::to_string(opt.generations) + " for each of --ranks " + opt.ranks,
      evaluations * (opt.time / opt.scene.dt) * kSecondsPerBatchedStep / HardwareThreads(),
      opt.scene.allow_long);
  const Scene scene = LoadScene(opt.scene);

  if (MpiWorldSize() > 1) {  // launched by the command below, through mpirun
    // The worker ranks serve MeasureScale's evaluator and end there.
    const ScaleMeasurement m = MeasureScale(scene.model, scene.program, settings);
    std::printf("%s\n", MeasurementJson(m, settings.evaluator.threads).dump().c_str());
    return;
  }

  const bool mpi = MpiBuiltIn() && HaveMpirun(opt.mpirun);
  std::vector<int> counts = rank_counts;
  if (counts.front() != 1) counts.insert(counts.begin(), 1);  // the model's baseline
  std::vector<Row> rows;
  std::vector<std::string> skipped;
  for (const int ranks : counts) {
    if (StopRequested()) throw Stopped("bench scale stopped; nothing written");
    if (ranks > 1 && !mpi) {
      skipped.push_back(std::to_string(ranks));
      continue;
    }
    Progress("scale: " + std::to_string(ranks) + " rank" + (ranks > 1 ? "s" : "") +
             ", population " + std::to_string(opt.population) + ", " +
             std::to_string(opt.generations) + " generations");
    nlohmann::json j;
    if (ranks == 1) {
      j = MeasurementJson(MeasureScale(scene.model, scene.program, settings),
                          settings.evaluator.threads);
    } else {
      j = MeasureWithMpirun(opt, ranks);
    }
    rows.push_back(Summarise(j));
  }
  const RestLengthTable& example = GeometricRestLengths(scene.model, scene.program);
  const double table_bytes =
      static_cast<double>(example.length.size() * sizeof(double)) + sizeof(RunResult);
  const ClusterModel model = ModelFrom(opt, rows.front(), rows, settings, table_bytes);
  const int cores = HardwareThreads();
  const std::vector<long long> populations = {64, 256, 1024, 4096, 16384, 65536};
  const std::vector<int> cluster_ranks = {64, 1024};

  if (opt.json) {
    nlohmann::json j;
    j["cpu"] = CpuModel();
    j["cores"] = cores;
    j["mpi"] = mpi;
    j["population"] = opt.population;
    j["time_units"] = opt.time;
    j["precision"] = opt.precision;
    for (const Row& r : rows) {
      j["measured"].push_back({{"ranks", r.ranks},
                               {"threads_per_rank", r.threads},
                               {"oversubscribed", r.ranks * r.threads > cores},
                               {"evaluations_per_second", opt.population / r.evaluate},
                               {"seconds_generation", r.evaluate + r.decode},
                               {"seconds_compute", r.compute_max},
                               {"seconds_compute_mean", r.compute_mean},
                               {"seconds_communication", r.communication},
                               {"seconds_send", r.send},
                               {"seconds_decode", r.decode},
                               {"bytes_per_generation", r.bytes}});
    }
    j["model"] = {{"cores_per_rank", model.cores_per_rank},
                  {"lanes", model.lanes},
                  {"seconds_per_eval_core", model.seconds_per_eval},
                  {"serial_seconds_per_eval", model.serial_seconds_per_eval},
                  {"bytes_per_eval", model.bytes_per_eval},
                  {"latency_seconds", model.latency_seconds},
                  {"bytes_per_second", model.bytes_per_second},
                  {"time_units", opt.model_time}};
    for (const int n : cluster_ranks) {
      for (const long long p : populations) {
        const GenerationTime t = PredictGeneration(model, p, n);
        j["predicted"].push_back({{"ranks", n},
                                  {"population", p},
                                  {"seconds_generation", t.seconds_total},
                                  {"seconds_compute", t.seconds_compute},
                                  {"seconds_communication", t.seconds_communication},
                                  {"seconds_serial", t.seconds_serial},
                                  {"efficiency", t.efficiency}});
      }
      j["population_for_90_percent"][std::to_string(n)] = PopulationFor(model, n, 0.9);
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }

  std::printf(
      "bench scale: %s, %d hardware threads; population %d, %g time units per "
      "evaluation, %s, median of %d generations\n",
      CpuModel().c_str(), cores, opt.population, opt.time, opt.precision.c_str(), opt.generations);
  if (!skipped.empty()) {
    std::printf("not measured: %s ranks (%s)\n", opt.ranks.c_str(),
                MpiBuiltIn() ? "no mpirun in PATH" : "this hexgait was built without MPI");
  }
  std::printf("\n%5s %7s %10s %11s %9s %9s %9s %9s %8s\n", "ranks", "threads", "evals/s", "s/gen",
              "compute", "comm", "decode", "MB/gen", "speedup");
  for (const Row& r : rows) {
    std::printf("%5d %7d %10.1f %11.3f %9.3f %9.3f %9.4f %9.2f %7.2fx%s\n", r.ranks, r.threads,
                opt.population / r.evaluate, r.evaluate + r.decode, r.compute_max, r.communication,
                r.decode, r.bytes / 1e6, rows.front().evaluate / r.evaluate,
                r.ranks * r.threads > cores ? "  (oversubscribed)" : "");
  }
  std::printf(
      "\ncompute: the slowest rank's evaluation; comm: the rest of the Evaluate call (sends, "
      "receives, waiting); decode: rank 0 making the genomes and their tables.\n");
  std::printf(
      "\nmodel (docs/scaling.md): %d cores x %d lanes per rank, %.3g s per evaluation per core "
      "at %g time units, %.3g s serial and %.0f bytes per evaluation, latency %g us, %g GB/s\n",
      model.cores_per_rank, model.lanes, model.seconds_per_eval, opt.model_time,
      model.serial_seconds_per_eval, model.bytes_per_eval, opt.latency_us, opt.bandwidth_gbs);
  std::printf("%10s", "population");
  for (const int n : cluster_ranks) std::printf("   %4d ranks: s/gen  efficiency", n);
  std::printf("\n");
  for (const long long p : populations) {
    std::printf("%10lld", p);
    for (const int n : cluster_ranks) {
      const GenerationTime t = PredictGeneration(model, p, n);
      std::printf("   %17.3f  %9.1f%%", t.seconds_total, 100 * t.efficiency);
    }
    std::printf("\n");
  }
  for (const int n : cluster_ranks) {
    std::printf("population for 90%% efficiency on %d ranks: %lld\n", n,
                PopulationFor(model, n, 0.9));
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
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text");
  AddSceneOptions(cmd, opt->scene);
  Distributed(cmd);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
