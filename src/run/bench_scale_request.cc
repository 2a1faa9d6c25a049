// hexgait bench scale as a request (run/bench_request.h): evaluations per second for one large
// population on 1, 2, 4... MPI ranks of this machine, and the cluster model of docs/scaling.md
// fed with them. Each rank count other than 1 runs as `mpirun -np N hexgait bench scale ...`,
// whose rank 0 measures alone (ScaleResult::measured_alone) and prints JSON that this reads.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "eval/mpi_evaluator.h"
#include "run/bench_request.h"
#include "run/work_size.h"
#include "util/child_process.h"
#include "util/error.h"

namespace hexgait {
namespace {

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

ScaleBenchSettings MakeSettings(const ScaleRequest& opt) {
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

std::vector<std::string> ChildArgs(const ScaleRequest& opt, int ranks) {
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
ScaleMeasurement MeasureWithMpirun(const ScaleRequest& opt, int ranks) {
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

}  // namespace

ScaleResult MeasureScaling(const ScaleRequest& opt, const LogLine& note) {
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
  RefuseLongEvaluations("--population " + std::to_string(opt.population) + " x --generations " +
                            std::to_string(opt.generations) + " for each of --ranks " + opt.ranks,
                        scene.model, evaluations, settings.measure.evaluator.run, HardwareThreads(),
                        opt.scene.allow_long);

  if (MpiWorldSize() > 1) {  // launched by the command below, through mpirun
    // The worker ranks serve MeasureScale's evaluator and end there.
    ScaleResult result;
    result.measured_alone = true;
    result.measurement = MeasureScale(scene.model, scene.program, settings.measure);
    return result;
  }

  std::function<ScaleMeasurement(int)> on_ranks;
  if (MpiBuiltIn() && HaveMpirun(opt.mpirun)) {
    on_ranks = [&opt](int ranks) { return MeasureWithMpirun(opt, ranks); };
  }
  ScaleResult result;
  result.report = MeasureScaleAcrossRanks(scene.model, scene.program, settings, on_ranks, note);
  return result;
}

}  // namespace hexgait
