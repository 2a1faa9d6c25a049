// hexgait bench speed: how fast one creature-step is on each path, measured in one run, in
// rounds, so the ratios hold even on a busy machine. Every figure is the median of --repeats
// timings; one-core figures are the measuring thread's CPU time (a busy machine takes the core
// away for a while, which wall time would count), the all-cores figure is wall time.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/bench_common.h"
#include "app/bench_speed.h"
#include "app/cli_common.h"
#include "bench/naive_stepper.h"
#include "ga/evolution.h"
#include "search/ga_optimizer.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_kernel.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/median.h"

namespace hexgait {
namespace {

using Clock = std::chrono::steady_clock;

// Flops of one creature-step, counted from the kernel (sim/batch_kernel_impl.h), with a square
// root or a division counted as one flop (they cost far more):
//   per spring 34: difference 3, squared length 5, sqrt 1, 1/L 1, unit vector 3, rate 8
//                  (3 sub, 3 mul, 2 add), magnitude 4, force 3, scatter to both ends 6;
//   per particle 14: weight 1, Euler update 13 (h 1, positions 6, velocities 6);
//   per particle in ground contact 15: normal 3, friction scale 7 (incl. sqrt and div),
//                  normal force 1, friction force 4 (counted for the 6 feet).
constexpr int kFlopsPerSpring = 34;
constexpr int kFlopsPerParticle = 14;
constexpr int kFlopsPerContact = 15;

struct SpeedOptions {
  bool json = false;
  double seconds = 0.25;  // per timing
  int repeats = 5;
  int threads = 0;
  bool skip_evolve = false;
};

double Seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// One timed path: `run(steps)` simulates `creatures` x `steps` creature-steps.
struct Path {
  Path(std::string n, long long c, std::function<void(long long)> r)
      : name(std::move(n)), creatures(c), run(std::move(r)) {}
  std::string name;
  long long creatures = 1;
  std::function<void(long long)> run;
  long long steps = 0;
  std::vector<double> wall_ns, cpu_ns;  // per creature-step, one per repeat
};

// Sizes each path's runs at about `seconds` from one short run, then times them in rounds, each
// round running every path once, so a change in the machine's load hits all paths alike.
void TimeInRounds(const SpeedOptions& opt, std::vector<Path>& paths) {
  const long long probe = 4000;
  const long long most = std::llround(kPaperDuration / kPaperTimeStep);
  for (Path& p : paths) {
    const auto start = Clock::now();
    p.run(probe);
    p.steps = std::clamp(static_cast<long long>(opt.seconds * probe / Seconds(start)), probe, most);
  }
  for (int r = 0; r < opt.repeats; ++r) {
    for (Path& p : paths) {
      const double cpu = ThreadCpuSeconds();
      const auto start = Clock::now();
      p.run(p.steps);
      const double creature_steps = static_cast<double>(p.steps * p.creatures);
      p.wall_ns.push_back(Seconds(start) * 1e9 / creature_steps);
      p.cpu_ns.push_back((ThreadCpuSeconds() - cpu) * 1e9 / creature_steps);
    }
  }
}

void Run(const SpeedOptions& opt) {
  if (!(opt.seconds > 0 && opt.seconds <= 60)) throw InputError("--seconds must be in (0, 60]");
  if (opt.repeats < 1 || opt.repeats > 100) throw InputError("--repeats must be in [1, 100]");
  if (opt.threads < 0 || opt.threads > 1024) throw InputError("--threads must be in [0, 1024]");
  const Scene scene = LoadScene(SceneOptions{});
  const CreatureModel& model = scene.model;
  const MotorProgram& program = scene.program;
  const int threads = ResolveThreadCount(opt.threads);
  const BatchIsa isa = BestBatchIsa();

  // Random genomes, the same for every path; one creature uses the first.
  std::vector<Genome> genomes;
  {
    Rng rng = Rng::ForStream(2024, 0);
    const auto layout = MakeGenomeLayout(model, program, false);
    for (int i = 0; i < kMaxBatchLanes; ++i) {
      Genome g(layout);
      for (int k = 0; k < g.num_genes(); ++k) {
        g.set_gene(k, static_cast<int>(rng.NextBelow(16)) - 8);
      }
      genomes.push_back(std::move(g));
    }
  }
  auto options_for = [](long long steps) {
    RunOptions o;
    o.duration = static_cast<double>(steps) * o.dt;
    return o;
  };

  std::vector<Path> paths;
  // (a) The plain array-of-structs Eigen loop, with the same controller.
  const RestLengthTable table = PerturbedRestLengths(model, program, genomes[0]);
  paths.emplace_back("naive: array-of-structs Eigen loop", 1, [&](long long steps) {
    MotorController controller(model, program, table, kPaperTimeStep);
    NaiveState s = MakeNaiveState(model);
    std::vector<double> rest = model.rest_length;
    for (long long k = 0; k < steps; ++k) {
      controller.Update(k, rest.data());
      NaiveEulerStep(model, rest.data(), s, kPaperTimeStep);
    }
    if (!(s.position[0].x() < 1e300)) std::fputc(' ', stderr);  // keep it live
  });
  // (b) The scalar structure-of-arrays path, as EvaluateGenome runs it.
  paths.emplace_back("single: scalar structure of arrays", 1, [&](long long steps) {
    EvaluateGenome(model, program, genomes[0], options_for(steps));
  });
  // (c) Lanes on one core, for every compiled lane count, in double and in float.
  std::vector<std::vector<const Genome*>> batches;
  for (int lanes : kBatchLaneCounts) {
    std::vector<const Genome*> batch;
    for (int i = 0; i < lanes; ++i) batch.push_back(&genomes[i]);
    batches.push_back(batch);
  }
  const size_t first_double = paths.size();
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    for (size_t j = 0; j < batches.size(); ++j) {
      const int lanes = kBatchLaneCounts[j];
      std::string name = precision == Precision::kFloat ? "batched float: " : "batched: ";
      name += std::to_string(lanes) + (lanes == 1 ? " lane" : " lanes");
      paths.emplace_back(name, lanes, [&, j, lanes, precision](long long steps) {
        EvaluateGenomesBatched(model, program, batches[j], options_for(steps), lanes,
                               BatchIsa::kAuto, precision);
      });
    }
  }
  const size_t first_float = first_double + batches.size();
  // (e) The float creature kernel (sim/creature_simulation.h), where this CPU has it: the path
  // float batches of up to kCreatureKernelMaxBatch creatures take.
  const size_t first_creature = paths.size();
  if (CreatureSimulation::Available(model)) {
    for (int count = 1; count <= kCreatureKernelMaxBatch; count *= 2) {
      std::string name = "creature kernel (float): ";
      name += std::to_string(count) + (count == 1 ? " creature" : " creatures");
      paths.emplace_back(name, count, [&, count](long long steps) {
        const std::vector<const Genome*> batch(batches.back().begin(),
                                               batches.back().begin() + count);
        EvaluateGenomesWithCreatureKernel(model, program, batch, options_for(steps));
      });
    }
  }
  TimeInRounds(opt, paths);
  std::vector<double> cpu, wall;
  for (const Path& p : paths) {
    cpu.push_back(Median(p.cpu_ns));
    wall.push_back(Median(p.wall_ns));
  }
  const double naive = cpu[0], single = cpu[1];
  auto fastest = [&](size_t from, size_t to) {
    size_t best = from;
    for (size_t j = from; j < to; ++j) best = cpu[j] < cpu[best] ? j : best;
    return best;
  };
  const size_t best = fastest(first_double, first_float);
  const size_t best_f = fastest(first_float, first_creature);
  const int best_lanes = static_cast<int>(paths[best].creatures);
  const int best_lanes_f = static_cast<int>(paths[best_f].creatures);

  // (d) All cores: one batch of the best width per thread; wall time.
  std::vector<Path> all;
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    const size_t b = precision == Precision::kFloat ? best_f - first_float : best - first_double;
    all.emplace_back("all cores", static_cast<long long>(threads) * kBatchLaneCounts[b],
                     [&, b, precision](long long steps) {
                       std::vector<std::thread> pool;
                       for (int t = 0; t < threads; ++t) {
                         pool.emplace_back([&, b, precision] {
                           EvaluateGenomesBatched(model, program, batches[b], options_for(steps),
                                                  kBatchLaneCounts[b], BatchIsa::kAuto, precision);
                         });
                       }
                       for (std::thread& t : pool) t.join();
                     });
  }
  TimeInRounds(opt, all);
  const double all_cores = Median(all[0].wall_ns);
  const double all_cores_f = Median(all[1].wall_ns);

  // Peak: independent vector multiplies and adds on this core (thread CPU time, like the
  // one-core paths), and the floor set by square roots and divisions alone: one of each per
  // spring and per foot in contact, at this core's measured throughput for full vectors.
  const int pairs = model.num_springs() + static_cast<int>(model.legs.size());
  const int flops = kFlopsPerSpring * model.num_springs() +
                    kFlopsPerParticle * model.num_particles() +
                    kFlopsPerContact * static_cast<int>(model.legs.size());
  struct Limits {
    double peak_gflops = 0, sqrt_div_floor = 0;
  };
  auto limits = [&](Precision precision) {
    std::vector<double> peak_samples, pair_samples;
    volatile double one = 1.0, zero = 0.0;
    for (int r = 0; r < opt.repeats; ++r) {
      const long long iterations = 20'000'000;
      double start = ThreadCpuSeconds();
      double sink = RunPeakLoop(isa, iterations, one, zero, precision);
      double ns = (ThreadCpuSeconds() - start) * 1e9;
      if (!(sink < 1e300)) std::fputc(' ', stderr);
      peak_samples.push_back(static_cast<double>(iterations) * PeakLoopFlops(isa, precision) / ns);
      const long long sqrt_iterations = 2'000'000;
      start = ThreadCpuSeconds();
      sink = RunSqrtDivLoop(isa, sqrt_iterations, one + 1.0, precision);
      ns = (ThreadCpuSeconds() - start) * 1e9;
      if (!(sink < 1e300)) std::fputc(' ', stderr);
      pair_samples.push_back(
          ns / (8.0 * static_cast<double>(sqrt_iterations) * NativeBatchLanes(isa, precision)));
    }
    return Limits{Median(peak_samples), Median(pair_samples) * pairs};
  };
  const Limits limits_d = limits(Precision::kDouble);
  const Limits limits_f = limits(Precision::kFloat);
  const double peak_gflops = limits_d.peak_gflops;
  const double sqrt_div_floor = limits_d.sqrt_div_floor;
  const double batched = cpu[best];
  const double batched_f = cpu[best_f];
  const double achieved_gflops = flops / batched;
  const double achieved_gflops_f = flops / batched_f;

  // The paper's whole experiment (`hexgait evolve --seed 1`): batched in double, in float, and
  // one creature at a time.
  double evolve_batched = 0, evolve_float = 0, evolve_scalar = 0;
  int evaluations = 0;
  if (!opt.skip_evolve) {
    std::vector<double> b, f, s;
    for (int r = 0; r < std::min(opt.repeats, 3); ++r) {
      EvolutionParams params;
      params.threads = threads;
      auto start = Clock::now();
      evaluations = Evolve(model, program, params, {}).total_evaluations;
      b.push_back(Seconds(start));
      params.precision = Precision::kFloat;
      start = Clock::now();
      Evolve(model, program, params, {});
      f.push_back(Seconds(start));
      params.precision = Precision::kDouble;
      params.batch_lanes = 1;
      start = Clock::now();
      Evolve(model, program, params, {});
      s.push_back(Seconds(start));
    }
    evolve_batched = Median(b);
    evolve_float = Median(f);
    evolve_scalar = Median(s);
  }

  const double steps_per_evaluation = kPaperDuration / kPaperTimeStep;
  const double eval_ms_batched = batched * steps_per_evaluation * 1e-6;
  const double eval_ms_float = batched_f * steps_per_evaluation * 1e-6;
  if (opt.json) {
    nlohmann::json j;
    j["cpu"] = CpuModel();
    j["kernel_isa"] = BatchIsaName(isa);
    j["threads"] = threads;
    j["repeats"] = opt.repeats;
    j["timing"] =
        "one-core paths: CPU time of the measuring thread (time given to other processes is "
        "not "
        "counted); *_wall: wall time; all cores: wall time";
    j["ns_per_creature_step_naive"] = naive;
    j["ns_per_creature_step_single"] = single;
    j["ns_per_creature_step_batched"] = batched;
    j["ns_per_creature_step_naive_wall"] = wall[0];
    j["ns_per_creature_step_single_wall"] = wall[1];
    j["ns_per_creature_step_batched_wall"] = wall[best];
    j["batched_lanes"] = best_lanes;
    j["ns_per_creature_step_all_cores"] = all_cores;
    nlohmann::json lanes = nlohmann::json::object(), lanes_f = nlohmann::json::object();
    for (size_t k = first_double; k < first_creature; ++k) {
      (k < first_float ? lanes : lanes_f)[std::to_string(paths[k].creatures)] = {{"cpu", cpu[k]},
                                                                                 {"wall", wall[k]}};
    }
    j["ns_per_creature_step_by_lanes"] = lanes;
    j["ns_per_creature_step_batched_float"] = batched_f;
    j["ns_per_creature_step_batched_float_wall"] = wall[best_f];
    j["batched_float_lanes"] = best_lanes_f;
    j["ns_per_creature_step_all_cores_float"] = all_cores_f;
    j["ns_per_creature_step_by_lanes_float"] = lanes_f;
    nlohmann::json creature = nlohmann::json::object();
    for (size_t k = first_creature; k < paths.size(); ++k) {
      creature[std::to_string(paths[k].creatures)] = {{"cpu", cpu[k]}, {"wall", wall[k]}};
    }
    j["ns_per_creature_step_creature_kernel"] = creature;  // empty without AVX-512
    j["speedup_batched_float_vs_naive"] = naive / batched_f;
    j["evaluation_ms_batched_float_one_core"] = eval_ms_float;
    j["evaluations_per_second_float"] = 1e9 / (all_cores_f * steps_per_evaluation);
    j["gflops_batched_float_one_core"] = achieved_gflops_f;
    j["peak_gflops_float_one_core"] = limits_f.peak_gflops;
    j["ns_per_creature_step_sqrt_div_floor_float"] = limits_f.sqrt_div_floor;
    j["speedup_batched_vs_naive"] = naive / batched;
    j["speedup_batched_vs_single"] = single / batched;
    j["speedup_batched_vs_naive_wall"] = wall[0] / wall[best];
    j["evaluation_ms_batched_one_core"] = eval_ms_batched;
    j["evaluations_per_second"] = 1e9 / (all_cores * steps_per_evaluation);
    j["evaluations_per_second_one_core"] = 1e9 / (batched * steps_per_evaluation);
    j["flops_per_creature_step"] = flops;
    j["gflops_batched_one_core"] = achieved_gflops;
    j["peak_gflops_one_core"] = peak_gflops;
    j["fraction_of_peak"] = achieved_gflops / peak_gflops;
    j["sqrt_div_pairs_per_creature_step"] = pairs;
    j["ns_per_creature_step_sqrt_div_floor"] = sqrt_div_floor;
    if (!opt.skip_evolve) {
      j["paper_experiment_seconds"] = evolve_batched;
      j["paper_experiment_seconds_one_at_a_time"] = evolve_scalar;
      j["paper_experiment_seconds_float"] = evolve_float;
      j["paper_experiment_evaluations"] = evaluations;
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf(
      "hexgait bench speed: %s, %s kernel (%d doubles per vector), %d thread%s, medians "
      "of %d\n\n",
      CpuModel().c_str(), BatchIsaName(isa).c_str(), NativeBatchLanes(isa), threads,
      threads == 1 ? "" : "s", opt.repeats);
  std::printf(
      "| path | ns per creature-step, CPU time | wall time | evaluations/s (CPU time) | vs "
      "naive "
      "(CPU time) |\n|---|---|---|---|---|\n");
  for (size_t k = 0; k < paths.size(); ++k) {
    std::printf("| %s, one core | %.1f | %.1f | %.1f | %.1fx |\n", paths[k].name.c_str(), cpu[k],
                wall[k], 1e9 / (cpu[k] * steps_per_evaluation), naive / cpu[k]);
  }
  std::printf("| batched: %d lanes x %d threads | | %.1f | %.1f (wall) | |\n", best_lanes, threads,
              all_cores, 1e9 / (all_cores * steps_per_evaluation));
  std::printf("| batched float: %d lanes x %d threads | | %.1f | %.1f (wall) | |\n", best_lanes_f,
              threads, all_cores_f, 1e9 / (all_cores_f * steps_per_evaluation));
  std::printf(
      "\none evaluation (1000 time units) batched on one core: %.1f ms in double, %.1f ms in "
      "float\n",
      eval_ms_batched, eval_ms_float);
  if (!opt.skip_evolve) {
    std::printf(
        "the paper's experiment (evolve --seed 1, %d evaluations): %.2f s batched, %.2f s in "
        "float (creature kernel where available), %.2f s one creature at a time\n",
        evaluations, evolve_batched, evolve_float, evolve_scalar);
  }
  std::printf(
      "flops per creature-step: %d (sqrt and division counted as 1); batched: %.1f GFLOP/s, "
      "%.0f%% of this core's measured double peak of %.1f GFLOP/s (vector multiply + add, no "
      "FMA); float: %.1f GFLOP/s, %.0f%% of %.1f\n",
      flops, achieved_gflops, 100 * achieved_gflops / peak_gflops, peak_gflops, achieved_gflops_f,
      100 * achieved_gflops_f / limits_f.peak_gflops, limits_f.peak_gflops);
  std::printf(
      "square roots and divisions alone (%d of each per creature-step, full vectors): "
      "%.1f ns per creature-step in double (%.0f%% of the batched time), %.1f ns in float "
      "(%.0f%%)\n",
      pairs, sqrt_div_floor, 100 * sqrt_div_floor / batched, limits_f.sqrt_div_floor,
      100 * limits_f.sqrt_div_floor / batched_f);
}

}  // namespace

void AddBenchSpeed(CLI::App& bench) {
  auto opt = std::make_shared<SpeedOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "speed", "ns per creature-step: naive loop, scalar, batched lanes, all cores; flop rate");
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of the table");
  cmd->add_option("--seconds", opt->seconds, "Approximate length of each timing")
      ->capture_default_str();
  cmd->add_option("--repeats", opt->repeats, "Timings per figure (the median is reported)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->threads, "Threads for the all-cores figure (0: all cores)")
      ->capture_default_str();
  cmd->add_flag("--skip-evolve", opt->skip_evolve,
                "Do not time the paper's whole experiment (hexgait evolve --seed 1)");
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
