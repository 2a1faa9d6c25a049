// hexgait sweep: whole independent evolve runs, one per seed, into DIR/seed-K/, then
// DIR/summary.csv and DIR/table.md (the seeds table of docs/results.md). The runs share this
// machine's threads, or, under mpirun, go to ranks as they become free (rank 0 hands them out
// and writes the summary; each rank writes its seeds' folders, so DIR must be on a file system
// every rank sees). Every seed's folder holds the same bytes `hexgait evolve --seed K` writes.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.h"
#include "app/evolve_options.h"
#include "app/sweep_summary.h"
#include "eval/evaluator.h"
#include "eval/mpi_evaluator.h"
#include "eval/mpi_tasks.h"
#include "motor/assets.h"
#include "run/io_paths.h"
#include "run/run_folder.h"
#include "record/run_record.h"
#include "run/run_state.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/folder_lock.h"
#include "util/json_file.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct SweepOptions {
  EvolveOptions run;  // every GA flag; seed and folder are set per run
  std::string seeds = "1-20";
  std::string out_dir = "out/sweep";
  bool quiet = false;
};

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

// "1-20", "3,5,9", "1-4,10": in the order given, each seed once.
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

std::string SeedFolder(const std::string& out_dir, unsigned long long seed) {
  return out_dir + "/seed-" + std::to_string(seed);
}

// The parameters a seed's run.json must have for the seed to count as done by this sweep.
nlohmann::json ExpectedParameters(const EvolveSettings& run) {
  const EvolutionParams& p = run.params;
  nlohmann::json expected = {
      {"generations", p.generations}, {"symmetric", p.symmetric},
      {"early_stop", run.early_stop}, {"time", run.time},
      {"dt", run.scene.dt},           {"integrator", run.scene.integrator},
      {"precision", run.precision},   {"creature", CreatureLabel(run.scene.creature_path)}};
  if (run.algorithm == "ga") {
    expected["population"] = p.population;
    expected["crossover_rate"] = p.crossover_rate;
    expected["mutation_rate"] = p.mutation_rate;
    expected["initial_mutation_rate"] = p.initial_mutation_rate;
    expected["elites"] = p.elites;
  } else {
    // run.json names every algorithm but the paper's GA, and records the population it used
    // (CMA-ES's default when --population was not given).
    expected["algorithm"] = run.algorithm;
    expected["sigma"] = p.sigma;
    if (run.population_given) {
      expected["population"] = p.population;
    }
  }
  return expected;
}

// True if the seed's folder holds a finished run of this sweep's parameters; throws if it holds
// a finished run of other parameters (mixing them would make the table meaningless).
bool SeedIsDone(const std::string& folder, const nlohmann::json& expected) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(folder + "/run.json", ec)) return false;
  try {
    RefuseUnfinishedRun(folder, "--out");
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
  return true;
}

// One seed's run, with this process's threads only.
void RunSeed(const SweepOptions& opt, unsigned long long seed, int threads) {
  EvolveSettings run = SettingsOf(opt.run);
  run.params.seed = seed;
  run.params.threads = threads;
  run.out_dir = SeedFolder(opt.out_dir, seed);
  run.local_only = true;
  RunEvolve(run);
}

// Runs `seeds` on this machine's threads: as many runs at once as there are threads, each with
// its share of them (results never depend on the thread count).
void RunOnThreads(const SweepOptions& opt, const std::vector<unsigned long long>& seeds,
                  const std::function<void(unsigned long long)>& on_done) {
  const int threads = ResolveThreadCount(opt.run.settings.params.threads);
  const int workers = std::max(1, std::min<int>(threads, static_cast<int>(seeds.size())));
  const int threads_per_run = std::max(1, threads / workers);
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex mutex;
  auto work = [&] {
    for (;;) {
      if (failed.load()) return;
      const size_t i = next.fetch_add(1);
      if (i >= seeds.size()) return;
      try {
        RunSeed(opt, seeds[i], threads_per_run);
        std::lock_guard<std::mutex> lock(mutex);
        on_done(seeds[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!first_error) first_error = std::current_exception();
        failed.store(true);
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

void Run(const SweepOptions& opt) {
  StopIsPolled();  // each run stops after its next generation's checkpoint
  const std::vector<unsigned long long> seeds = ParseSeeds(opt.seeds);
  const nlohmann::json expected = ExpectedParameters(SettingsOf(opt.run));
  // Under mpirun, the worker ranks run the seeds rank 0 hands out, and end here.
  JoinMpiTaskPool([&](long long seed) {
    RunSeed(opt, static_cast<unsigned long long>(seed),
            ResolveThreadCount(opt.run.settings.params.threads));
  });
  {
    IoPaths paths = SceneInputs(opt.run.settings.scene);
    paths.Output("--out", opt.out_dir + "/summary.csv");
    paths.Output("--out", opt.out_dir + "/table.md");
    paths.Check();
  }
  // A new or empty folder, or an earlier sweep's, which this one continues.
  const RunFolder folder(opt.out_dir, "--out", "sweep", {"summary.csv", "table.md"});
  std::vector<unsigned long long> pending;
  for (unsigned long long seed : seeds) {
    if (!SeedIsDone(SeedFolder(opt.out_dir, seed), expected)) pending.push_back(seed);
  }
  const int ranks = MpiWorldSize();
  if (!opt.quiet) {
    std::fprintf(stderr, "sweep: %zu seeds (%zu already done), population %d, %d generations, %s\n",
                 seeds.size(), seeds.size() - pending.size(), opt.run.settings.params.population,
                 opt.run.settings.params.generations,
                 ranks > 1 ? (std::to_string(ranks - 1) + " MPI ranks running seeds").c_str()
                           : (std::to_string(ResolveThreadCount(opt.run.settings.params.threads)) +
                              " threads")
                                 .c_str());
  }
  size_t done = seeds.size() - pending.size();
  auto on_done = [&](unsigned long long seed) {
    ++done;
    if (opt.quiet) return;
    const SeedSummary s = ReadSeedSummary(SeedFolder(opt.out_dir, seed));
    std::fprintf(stderr, "sweep: seed %llu done (%zu of %zu): best %.4f, %.2fx unoptimized%s\n",
                 seed, done, seeds.size(), s.best_distance, s.ratio, s.best_fell ? ", falls" : "");
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
  std::printf("%s", table.c_str());
  if (!opt.quiet) {
    std::fprintf(stderr, "sweep: wrote %s/seed-*/, %s/summary.csv and %s/table.md\n",
                 opt.out_dir.c_str(), opt.out_dir.c_str(), opt.out_dir.c_str());
  }
}

}  // namespace

void RegisterSweep(CLI::App& app) {
  auto opt = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Evolve once per seed (DIR/seed-K/, as 'evolve --seed K' writes it), then DIR/summary.csv "
      "and the seeds table; on threads, or across MPI ranks under mpirun");
  cmd->add_option("--seeds", opt->seeds, "Seeds to run: 1-20, 1,4,9 or 1-4,10")
      ->capture_default_str();
  cmd->add_option("--out", opt->out_dir,
                  "Folder for seed-K/ runs, summary.csv and table.md; an earlier sweep's "
                  "folder is continued (its finished seeds are kept)")
      ->capture_default_str();
  cmd->add_flag("--quiet", opt->quiet, "Print only the table");
  AddEvolveRunOptions(cmd, opt->run);
  Distributed(cmd);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
