// hexgait bench speed: how fast one creature-step is on each path, measured in one run, in
// rounds, so the ratios hold even on a busy machine (MeasureSpeedOfPaths, run/bench_request.h,
// measures; this prints).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "run/bench_request.h"

namespace hexgait {
namespace {

struct SpeedOptions {
  bool json = false;
  SpeedRequest request;
  bool skip_evolve = false;
};

void PrintTable(const SpeedReport& r) {
  const double naive = r.rows[r.naive].cpu_ns;
  const double batched = r.rows[r.best].cpu_ns, batched_f = r.rows[r.best_float].cpu_ns;
  const double steps = r.steps_per_evaluation;
  std::printf(
      "hexgait bench speed: %s, %s kernel (%d doubles per vector), %d thread%s, medians "
      "of %d\n\n",
      r.cpu.c_str(), r.kernel_isa.c_str(), r.native_lanes, r.threads, r.threads == 1 ? "" : "s",
      r.repeats);
  std::printf(
      "| path | ns per creature-step, CPU time | wall time | evaluations/s (CPU time) | vs "
      "naive "
      "(CPU time) |\n|---|---|---|---|---|\n");
  for (const SpeedRow& row : r.rows) {
    std::printf("| %s, one core | %.1f | %.1f | %.1f | %.1fx |\n", row.name.c_str(), row.cpu_ns,
                row.wall_ns, 1e9 / (row.cpu_ns * steps), naive / row.cpu_ns);
  }
  std::printf("| batched: %d lanes x %d threads | | %.1f | %.1f (wall) | |\n", r.best_lanes,
              r.threads, r.all_cores_ns, 1e9 / (r.all_cores_ns * steps));
  std::printf("| batched float: %d lanes x %d threads | | %.1f | %.1f (wall) | |\n",
              r.best_lanes_float, r.threads, r.all_cores_float_ns,
              1e9 / (r.all_cores_float_ns * steps));
  std::printf(
      "\none evaluation (1000 time units) batched on one core: %.1f ms in double, %.1f ms in "
      "float\n",
      r.evaluation_ms, r.evaluation_ms_float);
  for (const SpeedReport::RefillWorkload& w : r.refill) {
    std::printf(
        "the repertoire's workload (%d children of %s, %.0f%% fall; stop at the fall, double, %d "
        "threads): %.1f evaluations/s with finished lanes refilled, %.1f kept to their batch's "
        "end: %.2fx\n",
        w.children, w.parents.c_str(), 100 * w.fell, r.threads, w.refilled_evals_per_s,
        w.kept_evals_per_s, w.ratio());
  }
  if (r.paper_experiment_timed) {
    std::printf(
        "the paper's experiment (evolve --seed 1, %d evaluations): %.2f s batched, %.2f s in "
        "float (creature kernel where available), %.2f s one creature at a time\n",
        r.paper_evaluations, r.paper_seconds, r.paper_seconds_float, r.paper_seconds_one_at_a_time);
  }
  std::printf(
      "flops per creature-step: %d (sqrt and division counted as 1); batched: %.1f GFLOP/s, "
      "%.0f%% of this core's measured double peak of %.1f GFLOP/s (vector multiply + add, no "
      "FMA); float: %.1f GFLOP/s, %.0f%% of %.1f\n",
      r.flops_per_creature_step, r.gflops, 100 * r.gflops / r.peak_gflops, r.peak_gflops,
      r.gflops_float, 100 * r.gflops_float / r.peak_gflops_float, r.peak_gflops_float);
  std::printf(
      "square roots and divisions alone (%d of each per creature-step, full vectors): "
      "%.1f ns per creature-step in double (%.0f%% of the batched time), %.1f ns in float "
      "(%.0f%%)\n",
      r.sqrt_div_pairs, r.sqrt_div_floor_ns, 100 * r.sqrt_div_floor_ns / batched,
      r.sqrt_div_floor_float_ns, 100 * r.sqrt_div_floor_float_ns / batched_f);
}

void Run(const SpeedOptions& opt) {
  const SpeedReport report = MeasureSpeedOfPaths(opt.request);
  if (opt.json) {
    std::printf("%s\n", SpeedReportJson(report).dump(2).c_str());
  } else {
    PrintTable(report);
  }
}

}  // namespace

void AddBenchSpeed(CLI::App& bench) {
  auto opt = std::make_shared<SpeedOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "speed", "ns per creature-step: naive loop, scalar, batched lanes, all cores; flop rate");
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of the table");
  cmd->add_option("--seconds", opt->request.settings.seconds, "Approximate length of each timing")
      ->capture_default_str();
  cmd->add_option("--repeats", opt->request.settings.repeats,
                  "Timings per figure (the median is reported)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->request.settings.threads,
                  "Threads for the all-cores figure (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--repertoire-children", opt->request.settings.repertoire_children,
                  "Children of the evolved gait evaluated as the repertoire does, with lanes "
                  "refilled and kept (0: skip)")
      ->capture_default_str();
  cmd->add_flag("--skip-evolve", opt->skip_evolve,
                "Do not time the paper's whole experiment (hexgait evolve --seed 1)");
  cmd->callback([opt] {
    opt->request.time_paper_experiment = !opt->skip_evolve;
    Run(*opt);
  });
}

}  // namespace hexgait
