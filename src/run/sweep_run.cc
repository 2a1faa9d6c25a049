#include "run/sweep_run.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "eval/evaluator.h"
#include "eval/mpi_evaluator.h"
#include "eval/mpi_tasks.h"
#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "motor/assets.h"
#include "record/run_record.h"
#include "run/io_paths.h"
#include "run/run_folder.h"
#include "run/run_state.h"
#include "run/work_size.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/parallel_for.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

constexpr size_t kMaxSeeds = 100000;
constexpr unsigned long long kMaxSeed = 9223372036854775807ULL;  // MPI sends it as long long

unsigned long long ParseSeed(const std::string& item, const std::string& text) {
  const bool digits =
      !item.empty() && item.size() <= 19 &&
      std::all_of(item.begin(), item.end(), [](char c) { return c >= '0' && c <= '9'; });
  const unsigned long long value = digits ? std::strtoull(item.c_str(), nullptr, 10) : 0;
  if (!digits || value > kMaxSeed) {
    throw InputError("--seeds '" + text + "': '" + item +
                     "' is not a seed (whole numbers from 0 to 9223372036854775807)");
  }
  return value;
}

}  // namespace

std::vector<unsigned long long> ParseSeeds(const std::string& text) {
  std::vector<unsigned long long> seeds;
  std::set<unsigned long long> seen;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t dash = item.find('-');
    unsigned long long first = 0, last = 0;
    if (dash == std::string::npos) {
      first = last = ParseSeed(item, text);
    } else {
      first = ParseSeed(item.substr(0, dash), text);
      last = ParseSeed(item.substr(dash + 1), text);
      if (last < first) {
        throw InputError("--seeds '" + text + "': range '" + item + "' runs backwards");
      }
    }
    if (last - first >= kMaxSeeds || seeds.size() + (last - first) >= kMaxSeeds) {
      throw InputError("--seeds '" + text + "': more than " + std::to_string(kMaxSeeds) + " seeds");
    }
    for (unsigned long long s = first;; ++s) {
      if (!seen.insert(s).second) {
        throw InputError("--seeds '" + text + "': seed " + std::to_string(s) + " appears twice");
      }
      seeds.push_back(s);
      if (s == last) break;
    }
  }
  if (text.empty() || text.back() == ',' || seeds.empty()) {
    throw InputError("--seeds '" + text + "': expected seeds like 1-20 or 1,4,9");
  }
  return seeds;
}

namespace {

std::string SeedFolder(const std::string& out_dir, unsigned long long seed) {
  return out_dir + "/seed-" + std::to_string(seed);
}

// The parameters a seed's run.json must have for the seed to count as done by this sweep.
nlohmann::json ExpectedParameters(const EvolveSettings& run) {
  const EvolutionParams p = SearchParamsOf(run);
  nlohmann::json expected = {
      {"generations", p.generations}, {"symmetric", p.symmetric},
      {"early_stop", run.early_stop}, {"time", run.time},
      {"dt", run.scene.dt},           {"integrator", run.scene.integrator},
      {"precision", run.precision},   {"creature", CreatureLabel(run.scene.creature_path)}};
  expected.update(ParamsToJson(p.settings));
  // run.json names every optimizer but the paper's GA, and records the population it used: an
  // optimizer's own default (CMA-ES's lambda) is not known until it runs.
  if (run.algorithm != kOriginalEvolveAlgorithm) expected["algorithm"] = run.algorithm;
  if (p.population != 0) expected["population"] = p.population;
  return expected;
}

// True if the seed's folder holds a finished run of this sweep's parameters; throws if it holds
// a finished run of other parameters (mixing them would make the table meaningless).
// `fingerprint`: of this sweep's creature and motor program (SceneFingerprint), which the
// seed's checkpoint must record: the same --creature path with other content, or another
// --motor, is another experiment.
bool SeedIsDone(const std::string& folder, const nlohmann::json& expected,
                const std::string& fingerprint) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(folder + "/run.json", ec)) return false;
  try {
    RefuseUnfinishedRun(folder, "--out", "evolve");
  } catch (const InputError&) {
    return false;  // interrupted: run it again
  }
  // The record as evolve writes it now, so a file from older hexgait compares by today's keys.
  const std::string path = folder + "/run.json";
  const std::string text = ReadTextFile(path);
  nlohmann::json run;
  try {
    run = RunRecordJson(ParseRunRecord(text, path));
  } catch (const InputError&) {
    return false;  // not a run.json: run the seed again
  }
  for (const auto& [key, value] : expected.items()) {
    if (!run.contains(key) || run[key] != value) {
      throw InputError("--out: '" + folder + "' holds a run with " + key + " " +
                       (run.contains(key) ? run[key].dump() : "missing") + ", not " + value.dump() +
                       "; use another --out for other parameters");
    }
  }
  const std::string checkpoint = folder + "/checkpoint.json";
  if (std::filesystem::is_regular_file(checkpoint, ec)) {
    const std::string recorded =
        CheckpointSceneFingerprint(ReadTextFile(checkpoint, kMaxCheckpointBytes));
    if (!recorded.empty() && recorded != fingerprint) {
      throw InputError("--out: '" + folder +
                       "' holds a run of another creature or motor program (its scene "
                       "fingerprint differs); use another --out for other parameters");
    }
  }
  return true;
}

// One seed's run, with this process's threads only.
void RunSeed(const SweepSettings& opt, unsigned long long seed, int threads) {
  EvolveSettings run = opt.run;
  run.params.seed = seed;
  run.params.threads = threads;
  run.out_dir = SeedFolder(opt.out_dir, seed);
  run.local_only = true;
  RunEvolve(run);
}

// Runs `seeds` on this machine's threads: as many runs at once as there are threads, each with
// its share of them (results never depend on the thread count).
void RunOnThreads(const SweepSettings& opt, const std::vector<unsigned long long>& seeds,
                  const std::function<void(unsigned long long)>& on_done) {
  const int threads = ResolveThreadCount(opt.run.params.threads);
  const int workers = std::max(1, std::min<int>(threads, static_cast<int>(seeds.size())));
  const int threads_per_run = std::max(1, threads / workers);
  std::mutex mutex;  // on_done is called from one thread at a time
  ParallelFor(seeds.size(), workers, [&](size_t i) {
    RunSeed(opt, seeds[i], threads_per_run);
    const std::lock_guard<std::mutex> lock(mutex);
    on_done(seeds[i]);
  });
}

}  // namespace

SweepOutcome RunSweep(const SweepSettings& opt, const SweepObserver& observer) {
  const std::vector<unsigned long long> seeds = ParseSeeds(opt.seeds);
  const nlohmann::json expected = ExpectedParameters(opt.run);
  // Under mpirun, the worker ranks run the seeds rank 0 hands out, and end here.
  JoinMpiTaskPool([&](long long seed) {
    RunSeed(opt, static_cast<unsigned long long>(seed), ResolveThreadCount(opt.run.params.threads));
  });
  {
    IoPaths paths = SceneInputs(opt.run.scene);
    paths.Output("--out", opt.out_dir + "/summary.csv");
    paths.Output("--out", opt.out_dir + "/table.md");
    paths.Check();
  }
  const Scene scene = LoadScene(opt.run.scene);
  const std::string fingerprint = Hex(SceneFingerprint(scene.model, scene.program));
  {
    // The whole sweep, not one run at a time: each run may be short and their sum days.
    const int ranks = MpiWorldSize();
    // Under mpirun, every rank but the first runs seeds on this many threads (as this rank sees
    // its machine).
    const double workers =
        static_cast<double>(ResolveThreadCount(opt.run.params.threads)) * std::max(1, ranks - 1);
    RefuseLongRun(
        "--seeds " + opt.seeds + " is " + std::to_string(seeds.size()) + " runs",
        EstimatedEvolveSeconds(opt.run, scene) * static_cast<double>(seeds.size()) / workers,
        opt.run.scene.allow_long);
  }
  // A new or empty folder, or an earlier sweep's, which this one continues.
  const ResumableFolder folder(opt.out_dir, "--out", "sweep", {"summary.csv", "table.md"});
  std::vector<unsigned long long> pending;
  for (unsigned long long seed : seeds) {
    if (!SeedIsDone(SeedFolder(opt.out_dir, seed), expected, fingerprint)) {
      pending.push_back(seed);
    }
  }
  const int ranks = MpiWorldSize();
  if (observer.started) {
    observer.started(seeds.size(), seeds.size() - pending.size(),
                     ranks > 1 ? ranks - 1 : ResolveThreadCount(opt.run.params.threads), ranks > 1);
  }
  size_t done = seeds.size() - pending.size();
  auto on_done = [&](unsigned long long seed) {
    ++done;
    if (observer.seed_done) {
      observer.seed_done(ReadSeedSummary(SeedFolder(opt.out_dir, seed)), done, seeds.size());
    }
  };
  try {
    if (ranks > 1) {
      const std::vector<long long> tasks(pending.begin(), pending.end());
      MpiDispatchTasks(tasks,
                       [&](long long seed) { on_done(static_cast<unsigned long long>(seed)); });
    } else {
      RunOnThreads(opt, pending, on_done);
    }
  } catch (const Stopped&) {
    throw Stopped("the sweep stopped with " + std::to_string(done) + " of " +
                  std::to_string(seeds.size()) +
                  " seeds done; run the same command again to finish the others");
  }

  std::vector<SeedSummary> summaries;
  for (unsigned long long seed : seeds) {
    summaries.push_back(ReadSeedSummary(SeedFolder(opt.out_dir, seed)));
  }
  const std::string table = SeedTableMarkdown(summaries, opt.seeds);
  folder.Write("summary.csv", SummaryCsv(summaries));
  folder.Write("table.md", table);
  folder.Complete();
  return {table};
}

}  // namespace hexgait
