// hexgait bench early-stop: does --early-stop change fitness, and how much would stopping a
// fallen creature early change it? Random genomes, each run with and without early stop, and,
// for those that fall, the distance they still crawl after two more gait cycles.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {
namespace {

struct EarlyStopOptions {
  int genomes = 200;
  bool json = false;
  int threads = 0;
};

std::vector<Individual> Evaluate(const Scene& scene, const std::vector<Genome>& genomes,
                                 const RunOptions& options, int threads) {
  std::vector<Individual> population;
  std::vector<int> pending;
  for (const Genome& g : genomes) {
    pending.push_back(static_cast<int>(population.size()));
    population.push_back({g, {}, 0});
  }
  EvaluatorConfig config;
  config.run = options;
  config.threads = threads;
  const auto evaluator = MakeLocalEvaluator(scene.model, scene.program, config);
  EvaluatePending(*evaluator, scene.model, scene.program, population, pending);
  return population;
}

void Run(const EarlyStopOptions& opt) {
  if (opt.genomes < 1 || opt.genomes > 100000) {
    throw InputError("--genomes must be in [1, 100000]");
  }
  if (opt.threads < 0 || opt.threads > 1024) throw InputError("--threads must be in [0, 1024]");
  const Scene scene = LoadScene(SceneOptions{});
  const auto layout = MakeGenomeLayout(scene.model, scene.program, false);
  std::vector<Genome> genomes;
  Rng rng = Rng::ForStream(4242, 0);
  for (int i = 0; i < opt.genomes; ++i) {
    Genome g(layout);
    for (int k = 0; k < g.num_genes(); ++k) g.set_gene(k, static_cast<int>(rng.NextBelow(16)) - 8);
    genomes.push_back(std::move(g));
  }
  RunOptions off;
  RunOptions on = off;
  on.early_stop = true;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Individual> full = Evaluate(scene, genomes, off, opt.threads);
  const double seconds_off =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<Individual> early = Evaluate(scene, genomes, on, opt.threads);
  const double seconds_on =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - seconds_off;

  int fell = 0, stopped = 0;
  double max_difference = 0;
  long long steps_off = 0, steps_on = 0;
  std::vector<double> crawl;  // distance still covered from 2 cycles after the fall to the end
  for (size_t i = 0; i < genomes.size(); ++i) {
    const RunResult& a = full[i].result;
    const RunResult& b = early[i].result;
    fell += a.fell;
    stopped += b.stopped_early;
    steps_off += a.steps;
    steps_on += b.steps;
    max_difference = std::max(max_difference, std::fabs(full[i].fitness - early[i].fitness));
    const double cut = a.fall_time + 2 * scene.program.cycle_period;
    if (a.fell && !a.diverged && cut < off.duration) {
      RunOptions shorter = off;
      shorter.duration = cut;
      const RunResult r = EvaluateGenome(scene.model, scene.program, genomes[i], shorter);
      crawl.push_back(std::fabs(a.distance - r.distance));
    }
  }
  std::sort(crawl.begin(), crawl.end());
  const double crawl_median = crawl.empty() ? 0 : crawl[crawl.size() / 2];
  const double crawl_max = crawl.empty() ? 0 : crawl.back();

  if (opt.json) {
    nlohmann::json j;
    j["genomes"] = opt.genomes;
    j["fell"] = fell;
    j["stopped_early"] = stopped;
    j["max_fitness_difference"] = max_difference;
    j["steps_saved_fraction"] = 1.0 - static_cast<double>(steps_on) / steps_off;
    j["seconds_without"] = seconds_off;
    j["seconds_with"] = seconds_on;
    j["crawl_after_fall_plus_2_cycles_median"] = crawl_median;
    j["crawl_after_fall_plus_2_cycles_max"] = crawl_max;
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("%d random genomes, 1000 time units each: %d fell, %d stopped early\n", opt.genomes,
              fell, stopped);
  std::printf(
      "largest fitness change from --early-stop: %.3g; steps saved: %.1f%% (%.2f s "
      "without, %.2f s with)\n",
      max_difference, 100.0 * (1.0 - static_cast<double>(steps_on) / steps_off), seconds_off,
      seconds_on);
  std::printf(
      "distance fallen creatures still cover after fall + 2 cycles: median %.3f, max "
      "%.3f (%zu runs)\n",
      crawl_median, crawl_max, crawl.size());
}

}  // namespace

void AddBenchEarlyStop(CLI::App& bench) {
  auto opt = std::make_shared<EarlyStopOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "early-stop", "How much --early-stop saves and changes, over random genomes");
  cmd->add_option("--genomes", opt->genomes, "Random genomes to run")->capture_default_str();
  cmd->add_option("--threads", opt->threads, "Threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text");
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
