// hexgait bench early-stop: does --early-stop change fitness, and how much would stopping a
// fallen creature early change it? (MeasureEarlyStopOf, run/bench_request.h,
// measures; this prints.)
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "run/bench_request.h"

namespace hexgait {
namespace {

struct EarlyStopOptions {
  EarlyStopSettings settings;
  bool json = false;
};

void Run(const EarlyStopOptions& opt) {
  const EarlyStopReport r = MeasureEarlyStopOf(opt.settings);
  if (opt.json) {
    std::printf("%s\n", EarlyStopReportJson(r).dump(2).c_str());
    return;
  }
  std::printf("%d random genomes, 1000 time units each: %d fell, %d stopped early\n", r.genomes,
              r.fell, r.stopped_early);
  std::printf(
      "largest fitness change from --early-stop: %.3g; steps saved: %.1f%% (%.2f s "
      "without, %.2f s with)\n",
      r.max_fitness_difference, 100.0 * r.steps_saved_fraction, r.seconds_without, r.seconds_with);
  std::printf(
      "distance fallen creatures still cover after fall + 2 cycles: median %.3f, max "
      "%.3f (%zu runs)\n",
      r.crawl_median, r.crawl_max, r.crawl_runs);
}

}  // namespace

void AddBenchEarlyStop(CLI::App& bench) {
  auto opt = std::make_shared<EarlyStopOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "early-stop", "How much --early-stop saves and changes, over random genomes");
  cmd->add_option("--genomes", opt->settings.genomes, "Random genomes to run")
      ->capture_default_str();
  cmd->add_option("--threads", opt->settings.threads, "Threads (0: all cores)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text");
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
