#include "bench/early_stop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/median.h"

namespace hexgait {
namespace {

std::vector<Individual> Evaluate(const CreatureModel& model, const MotorProgram& program,
                                 const std::vector<Genome>& genomes, const RunOptions& options,
                                 int threads) {
  std::vector<Individual> population;
  std::vector<int> pending;
  for (const Genome& g : genomes) {
    pending.push_back(static_cast<int>(population.size()));
    population.push_back({g, {}, 0});
  }
  EvaluatorConfig config;
  config.run = options;
  config.threads = threads;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  EvaluatePending(*evaluator, model, program, population, pending);
  return population;
}

}  // namespace

EarlyStopReport MeasureEarlyStop(const CreatureModel& model, const MotorProgram& program,
                                 const EarlyStopSettings& settings) {
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Genome> genomes;
  Rng rng = Rng::ForStream(4242, 0);
  for (int i = 0; i < settings.genomes; ++i) {
    Genome g(layout);
    for (int k = 0; k < g.num_genes(); ++k) g.set_gene(k, static_cast<int>(rng.NextBelow(16)) - 8);
    genomes.push_back(std::move(g));
  }
  RunOptions off;
  RunOptions on = off;
  on.early_stop = true;
  const auto start = Clock::now();
  const std::vector<Individual> full = Evaluate(model, program, genomes, off, settings.threads);
  const double seconds_off = SecondsSince(start);
  const std::vector<Individual> early = Evaluate(model, program, genomes, on, settings.threads);
  const double seconds_on = SecondsSince(start) - seconds_off;

  EarlyStopReport report;
  report.genomes = settings.genomes;
  long long steps_off = 0, steps_on = 0;
  std::vector<double> crawl;  // distance still covered from 2 cycles after the fall to the end
  for (size_t i = 0; i < genomes.size(); ++i) {
    const RunResult& a = full[i].result;
    const RunResult& b = early[i].result;
    report.fell += a.fell;
    report.stopped_early += b.stopped_early;
    steps_off += a.steps;
    steps_on += b.steps;
    report.max_fitness_difference =
        std::max(report.max_fitness_difference, std::fabs(full[i].fitness - early[i].fitness));
    const double cut = a.fall_time + 2 * program.cycle_period;
    if (a.fell && !a.diverged && cut < off.duration) {
      RunOptions shorter = off;
      shorter.duration = cut;
      const RunResult r = EvaluateGenome(model, program, genomes[i], shorter);
      crawl.push_back(std::fabs(a.distance - r.distance));
    }
  }
  std::sort(crawl.begin(), crawl.end());
  report.steps_saved_fraction = 1.0 - static_cast<double>(steps_on) / steps_off;
  report.seconds_without = seconds_off;
  report.seconds_with = seconds_on;
  report.crawl_median = Median(crawl, 0);
  report.crawl_max = crawl.empty() ? 0 : crawl.back();
  report.crawl_runs = crawl.size();
  return report;
}

nlohmann::json EarlyStopReportJson(const EarlyStopReport& r) {
  nlohmann::json j;
  j["genomes"] = r.genomes;
  j["fell"] = r.fell;
  j["stopped_early"] = r.stopped_early;
  j["max_fitness_difference"] = r.max_fitness_difference;
  j["steps_saved_fraction"] = r.steps_saved_fraction;
  j["seconds_without"] = r.seconds_without;
  j["seconds_with"] = r.seconds_with;
  j["crawl_after_fall_plus_2_cycles_median"] = r.crawl_median;
  j["crawl_after_fall_plus_2_cycles_max"] = r.crawl_max;
  return j;
}

}  // namespace hexgait
