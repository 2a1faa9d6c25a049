#include "bench/speed.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <utility>

#include "bench/cpu_model.h"
#include "bench/naive_stepper.h"
#include "eval/evaluator.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "ga/variation.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_kernel.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/median.h"

namespace hexgait {
namespace {

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// One timed path: `run(steps)` simulates `creatures` x `steps` creature-steps. `run` is called
// once a timing, never inside the step loop.
struct Path {
  Path(std::string n, SpeedPathKind k, long long c, std::function<void(long long)> r)
      : name(std::move(n)), kind(k), creatures(c), run(std::move(r)) {}
  std::string name;
  SpeedPathKind kind;
  long long creatures = 1;
  std::function<void(long long)> run;
  long long steps = 0;
  std::vector<double> wall_ns, cpu_ns;  // per creature-step, one per repeat
};

// Sizes each path's runs at about `seconds` from one short run, then times them in rounds, each
// round running every path once, so a change in the machine's load hits all paths alike.
void TimeInRounds(const SpeedSettings& settings, std::vector<Path>& paths) {
  const long long probe = 4000;
  const long long most = std::llround(kPaperDuration / kPaperTimeStep);
  for (Path& p : paths) {
    const auto start = Clock::now();
    p.run(probe);
    p.steps = std::clamp(static_cast<long long>(settings.seconds * probe / SecondsSince(start)),
                         probe, most);
  }
  for (int r = 0; r < settings.repeats; ++r) {
    for (Path& p : paths) {
      const double cpu = ThreadCpuSeconds();
      const auto start = Clock::now();
      p.run(p.steps);
      const double creature_steps = static_cast<double>(p.steps * p.creatures);
      p.wall_ns.push_back(SecondsSince(start) * 1e9 / creature_steps);
      p.cpu_ns.push_back((ThreadCpuSeconds() - cpu) * 1e9 / creature_steps);
    }
  }
}

RunOptions OptionsFor(long long steps) {
  RunOptions o;
  o.duration = static_cast<double>(steps) * o.dt;
  return o;
}

// The fastest row of `kind` in CPU time (the first of equals); rows.size() when there is none.
size_t Fastest(const std::vector<SpeedRow>& rows, SpeedPathKind kind) {
  size_t best = rows.size();
  for (size_t j = 0; j < rows.size(); ++j) {
    if (rows[j].kind == kind && (best == rows.size() || rows[j].cpu_ns < rows[best].cpu_ns)) {
      best = j;
    }
  }
  return best;
}

struct Limits {
  double peak_gflops = 0, sqrt_div_floor = 0;
};

// Peak: independent vector multiplies and adds on this core (thread CPU time, like the one-core
// paths), and the floor set by square roots and divisions alone: one of each per spring and per
// foot in contact (`pairs`), at this core's measured throughput for full vectors.
Limits MeasureLimits(BatchIsa isa, Precision precision, int repeats, int pairs) {
  std::vector<double> peak_samples, pair_samples;
  volatile double one = 1.0, zero = 0.0;
  for (int r = 0; r < repeats; ++r) {
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
}

// `children` mutants (each bit flipped with probability 0.01) of parents drawn uniformly, as
// MAP-Elites draws elites.
std::vector<Genome> Mutants(const std::vector<Genome>& parents, int children, Rng& rng) {
  std::vector<Genome> out;
  for (int k = 0; k < children; ++k) {
    const Genome& parent = parents[rng.NextBelow(static_cast<uint32_t>(parents.size()))];
    std::vector<uint8_t> bits = parent.ToBits();
    MutateBits(bits, 0.01, rng);
    Genome child(parent.layout_ptr());
    child.FromBits(bits);
    out.push_back(std::move(child));
  }
  return out;
}

// One workload timed refilled and kept, in rounds; `results` gets the runs (the last round's).
SpeedReport::RefillWorkload TimeRefill(const CreatureModel& model, const MotorProgram& program,
                                       const std::vector<Genome>& genomes,
                                       const SpeedSettings& settings, int threads,
                                       std::vector<RunResult>* results) {
  std::vector<RestLengthTable> tables;
  for (const Genome& g : genomes) tables.push_back(PerturbedRestLengths(model, program, g));
  EvaluatorConfig config;
  config.run.stop_at_fall = true;
  config.threads = threads;
  config.stop_on_request = false;
  std::vector<double> refilled, kept;
  for (int r = 0; r < std::min(settings.repeats, 3); ++r) {
    for (bool refill : {true, false}) {
      config.refill_lanes = refill;
      const auto evaluator = MakeLocalEvaluator(model, program, config);
      const auto start = Clock::now();
      *results = evaluator->Evaluate(tables);
      (refill ? refilled : kept).push_back(SecondsSince(start));
    }
  }
  SpeedReport::RefillWorkload w;
  w.children = static_cast<int>(genomes.size());
  int fell = 0;
  for (const RunResult& result : *results) fell += result.fell ? 1 : 0;
  w.fell = static_cast<double>(fell) / w.children;
  w.refilled_evals_per_s = w.children / Median(refilled);
  w.kept_evals_per_s = w.children / Median(kept);
  return w;
}

// The repertoire's two workloads (SpeedReport::refill): the unoptimised program's children, then
// children of the standing ones among them, a standing archive's.
void MeasureRefill(const CreatureModel& model, const MotorProgram& program,
                   const SpeedSettings& settings, int threads, SpeedReport& report) {
  Rng rng = Rng::ForStream(2027, 0);
  const Genome unoptimized(MakeGenomeLayout(model, program, /*symmetric=*/false));
  const std::vector<Genome> first = Mutants({unoptimized}, settings.repertoire_children, rng);
  std::vector<RunResult> results;
  SpeedReport::RefillWorkload w = TimeRefill(model, program, first, settings, threads, &results);
  w.key = "unoptimized_children";
  w.parents = "the unoptimised program";
  report.refill.push_back(w);
  std::vector<Genome> standing;
  for (size_t k = 0; k < first.size(); ++k) {
    if (!results[k].fell && !results[k].diverged) standing.push_back(first[k]);
  }
  if (standing.empty()) return;  // no archive to draw from
  const std::vector<Genome> second = Mutants(standing, settings.repertoire_children, rng);
  w = TimeRefill(model, program, second, settings, threads, &results);
  w.key = "archive_children";
  w.parents = "a standing archive (the " + std::to_string(standing.size()) + " standing children)";
  report.refill.push_back(w);
}

}  // namespace

std::vector<Genome> SpeedGenomes(const CreatureModel& model, const MotorProgram& program,
                                 int count) {
  Rng rng = Rng::ForStream(2024, 0);
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Genome> genomes;
  for (int i = 0; i < count; ++i) {
    Genome& g = genomes.emplace_back(layout);
    for (int k = 0; k < g.num_genes(); ++k) {
      g.set_gene(k, kGeneMin + static_cast<int>(rng.NextBelow(kGeneMax - kGeneMin + 1)));
    }
  }
  return genomes;
}

SpeedReport MeasureSpeed(const CreatureModel& model, const MotorProgram& program,
                         const SpeedSettings& settings, const LogLine& note) {
  auto say = [&](const std::string& line) {
    if (note) note(line);
  };
  SpeedReport report;
  const BatchIsa isa = BestBatchIsa();
  const int threads = ResolveThreadCount(settings.threads);
  report.cpu = CpuModel();
  report.kernel_isa = BatchIsaName(isa);
  report.native_lanes = NativeBatchLanes(isa);
  report.threads = threads;
  report.repeats = settings.repeats;
  report.steps_per_evaluation = kPaperDuration / kPaperTimeStep;

  // The same genomes for every path; one creature uses the first.
  const std::vector<Genome> genomes = SpeedGenomes(model, program, kMaxBatchLanes);
  // One batch of genomes per compiled lane count.
  std::vector<std::vector<const Genome*>> batches;
  for (int lanes : kBatchLaneCounts) {
    std::vector<const Genome*> batch;
    for (int i = 0; i < lanes; ++i) batch.push_back(&genomes[i]);
    batches.push_back(batch);
  }

  // The one-core paths, in the order they are printed. A new path is one more entry here (a
  // new kind also needs its place in SpeedReportJson).
  std::vector<Path> paths;
  // (a) The plain array-of-structs Eigen loop, with the same controller.
  const RestLengthTable table = PerturbedRestLengths(model, program, genomes[0]);
  paths.emplace_back("naive: array-of-structs Eigen loop", SpeedPathKind::kNaive, 1,
                     [&](long long steps) {
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
  paths.emplace_back(
      "single: scalar structure of arrays", SpeedPathKind::kScalar, 1,
      [&](long long steps) { EvaluateGenome(model, program, genomes[0], OptionsFor(steps)); });
  // (c) Lanes on one core, for every compiled lane count, in double and in float.
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    const bool is_float = precision == Precision::kFloat;
    for (size_t j = 0; j < batches.size(); ++j) {
      const int lanes = kBatchLaneCounts[j];
      std::string name = is_float ? "batched float: " : "batched: ";
      name += std::to_string(lanes) + (lanes == 1 ? " lane" : " lanes");
      paths.emplace_back(name, is_float ? SpeedPathKind::kBatchedFloat : SpeedPathKind::kBatched,
                         lanes, [&, j, lanes, precision](long long steps) {
                           EvaluateGenomesBatched(model, program, batches[j], OptionsFor(steps),
                                                  lanes, BatchIsa::kAuto, precision);
                         });
    }
  }
  // (e) The float creature kernel (sim/creature_simulation.h), where this CPU has it: the path
  // float batches of up to kCreatureKernelMaxBatch creatures take.
  if (CreatureSimulation::Available(model)) {
    for (int count = 1; count <= kCreatureKernelMaxBatch; count *= 2) {
      std::string name = "creature kernel (float): ";
      name += std::to_string(count) + (count == 1 ? " creature" : " creatures");
      paths.emplace_back(name, SpeedPathKind::kCreatureKernel, count, [&, count](long long steps) {
        const std::vector<const Genome*> batch(batches.back().begin(),
                                               batches.back().begin() + count);
        EvaluateGenomesWithCreatureKernel(model, program, batch, OptionsFor(steps));
      });
    }
  }
  say("speed: " + std::to_string(paths.size()) + " paths on one core");
  TimeInRounds(settings, paths);
  for (const Path& p : paths) {
    report.rows.push_back(
        {p.name, p.kind, static_cast<int>(p.creatures), Median(p.cpu_ns), Median(p.wall_ns)});
  }
  report.naive = Fastest(report.rows, SpeedPathKind::kNaive);
  report.single = Fastest(report.rows, SpeedPathKind::kScalar);
  report.best = Fastest(report.rows, SpeedPathKind::kBatched);
  report.best_float = Fastest(report.rows, SpeedPathKind::kBatchedFloat);
  report.best_lanes = report.rows[report.best].creatures;
  report.best_lanes_float = report.rows[report.best_float].creatures;

  // (d) All cores: one batch of the best width per thread; wall time.
  std::vector<Path> all;
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    const int lanes = precision == Precision::kFloat ? report.best_lanes_float : report.best_lanes;
    const size_t b = static_cast<size_t>(
        std::find(std::begin(kBatchLaneCounts), std::end(kBatchLaneCounts), lanes) -
        std::begin(kBatchLaneCounts));
    all.emplace_back("all cores", SpeedPathKind::kBatched, static_cast<long long>(threads) * lanes,
                     [&, b, lanes, precision](long long steps) {
                       std::vector<std::thread> pool;
                       for (int t = 0; t < threads; ++t) {
                         pool.emplace_back([&, b, lanes, precision] {
                           EvaluateGenomesBatched(model, program, batches[b], OptionsFor(steps),
                                                  lanes, BatchIsa::kAuto, precision);
                         });
                       }
                       for (std::thread& t : pool) t.join();
                     });
  }
  say("speed: all cores, " + std::to_string(threads) + " threads");
  TimeInRounds(settings, all);
  report.all_cores_ns = Median(all[0].wall_ns);
  report.all_cores_float_ns = Median(all[1].wall_ns);

  say("speed: this core's peak");
  report.sqrt_div_pairs = model.num_springs() + static_cast<int>(model.legs.size());
  report.flops_per_creature_step = kFlopsPerSpring * model.num_springs() +
                                   kFlopsPerParticle * model.num_particles() +
                                   kFlopsPerContact * static_cast<int>(model.legs.size());
  const Limits limits_d =
      MeasureLimits(isa, Precision::kDouble, settings.repeats, report.sqrt_div_pairs);
  const Limits limits_f =
      MeasureLimits(isa, Precision::kFloat, settings.repeats, report.sqrt_div_pairs);
  report.peak_gflops = limits_d.peak_gflops;
  report.sqrt_div_floor_ns = limits_d.sqrt_div_floor;
  report.peak_gflops_float = limits_f.peak_gflops;
  report.sqrt_div_floor_float_ns = limits_f.sqrt_div_floor;
  const double batched = report.rows[report.best].cpu_ns;
  const double batched_f = report.rows[report.best_float].cpu_ns;
  report.gflops = report.flops_per_creature_step / batched;
  report.gflops_float = report.flops_per_creature_step / batched_f;
  report.evaluation_ms = batched * report.steps_per_evaluation * 1e-6;
  report.evaluation_ms_float = batched_f * report.steps_per_evaluation * 1e-6;

  // The paper's whole experiment (`hexgait evolve --seed 1`): batched in double, in float, and
  // one creature at a time.
  if (settings.paper_experiment) {
    say("speed: the paper's experiment");
    std::vector<double> b, f, s;
    for (int r = 0; r < std::min(settings.repeats, 3); ++r) {
      EvolutionParams params;
      params.threads = threads;
      auto start = Clock::now();
      const EvolutionResult result = settings.paper_experiment(params);
      b.push_back(SecondsSince(start));
      report.paper_evaluations = result.total_evaluations;
      params.precision = Precision::kFloat;
      start = Clock::now();
      settings.paper_experiment(params);
      f.push_back(SecondsSince(start));
      params.precision = Precision::kDouble;
      params.batch_lanes = 1;
      start = Clock::now();
      settings.paper_experiment(params);
      s.push_back(SecondsSince(start));
    }
    report.paper_experiment_timed = true;
    report.paper_seconds = Median(b);
    report.paper_seconds_float = Median(f);
    report.paper_seconds_one_at_a_time = Median(s);
  }
  if (settings.repertoire_children > 0) {
    say("speed: the repertoire's workloads, lanes refilled and kept");
    MeasureRefill(model, program, settings, threads, report);
  }
  return report;
}

nlohmann::json SpeedReportJson(const SpeedReport& r) {
  const double naive = r.rows[r.naive].cpu_ns, single = r.rows[r.single].cpu_ns;
  const double batched = r.rows[r.best].cpu_ns, batched_f = r.rows[r.best_float].cpu_ns;
  auto by_count = [&](SpeedPathKind kind) {
    nlohmann::json rows = nlohmann::json::object();
    for (const SpeedRow& row : r.rows) {
      if (row.kind == kind) {
        rows[std::to_string(row.creatures)] = {{"cpu", row.cpu_ns}, {"wall", row.wall_ns}};
      }
    }
    return rows;
  };
  nlohmann::json j;
  j["cpu"] = r.cpu;
  j["kernel_isa"] = r.kernel_isa;
  j["threads"] = r.threads;
  j["repeats"] = r.repeats;
  j["timing"] =
      "one-core paths: CPU time of the measuring thread (time given to other processes is "
      "not "
      "counted); *_wall: wall time; all cores: wall time";
  j["ns_per_creature_step_naive"] = naive;
  j["ns_per_creature_step_single"] = single;
  j["ns_per_creature_step_batched"] = batched;
  j["ns_per_creature_step_naive_wall"] = r.rows[r.naive].wall_ns;
  j["ns_per_creature_step_single_wall"] = r.rows[r.single].wall_ns;
  j["ns_per_creature_step_batched_wall"] = r.rows[r.best].wall_ns;
  j["batched_lanes"] = r.best_lanes;
  j["ns_per_creature_step_all_cores"] = r.all_cores_ns;
  j["ns_per_creature_step_by_lanes"] = by_count(SpeedPathKind::kBatched);
  j["ns_per_creature_step_batched_float"] = batched_f;
  j["ns_per_creature_step_batched_float_wall"] = r.rows[r.best_float].wall_ns;
  j["batched_float_lanes"] = r.best_lanes_float;
  j["ns_per_creature_step_all_cores_float"] = r.all_cores_float_ns;
  j["ns_per_creature_step_by_lanes_float"] = by_count(SpeedPathKind::kBatchedFloat);
  // Empty without AVX-512.
  j["ns_per_creature_step_creature_kernel"] = by_count(SpeedPathKind::kCreatureKernel);
  j["speedup_batched_float_vs_naive"] = naive / batched_f;
  j["evaluation_ms_batched_float_one_core"] = r.evaluation_ms_float;
  j["evaluations_per_second_float"] = 1e9 / (r.all_cores_float_ns * r.steps_per_evaluation);
  j["gflops_batched_float_one_core"] = r.gflops_float;
  j["peak_gflops_float_one_core"] = r.peak_gflops_float;
  j["ns_per_creature_step_sqrt_div_floor_float"] = r.sqrt_div_floor_float_ns;
  j["speedup_batched_vs_naive"] = naive / batched;
  j["speedup_batched_vs_single"] = single / batched;
  j["speedup_batched_vs_naive_wall"] = r.rows[r.naive].wall_ns / r.rows[r.best].wall_ns;
  j["evaluation_ms_batched_one_core"] = r.evaluation_ms;
  j["evaluations_per_second"] = 1e9 / (r.all_cores_ns * r.steps_per_evaluation);
  j["evaluations_per_second_one_core"] = 1e9 / (batched * r.steps_per_evaluation);
  j["flops_per_creature_step"] = r.flops_per_creature_step;
  j["gflops_batched_one_core"] = r.gflops;
  j["peak_gflops_one_core"] = r.peak_gflops;
  j["fraction_of_peak"] = r.gflops / r.peak_gflops;
  j["sqrt_div_pairs_per_creature_step"] = r.sqrt_div_pairs;
  j["ns_per_creature_step_sqrt_div_floor"] = r.sqrt_div_floor_ns;
  for (const SpeedReport::RefillWorkload& w : r.refill) {
    j["refill_ratio_" + w.key] = w.ratio();
    j["refill_parents_" + w.key] = w.parents;
    j["refill_children_" + w.key] = w.children;
    j["refill_fell_" + w.key] = w.fell;
    j["refill_refilled_evals_per_s_" + w.key] = w.refilled_evals_per_s;
    j["refill_kept_evals_per_s_" + w.key] = w.kept_evals_per_s;
  }
  if (r.paper_experiment_timed) {
    j["paper_experiment_seconds"] = r.paper_seconds;
    j["paper_experiment_seconds_one_at_a_time"] = r.paper_seconds_one_at_a_time;
    j["paper_experiment_seconds_float"] = r.paper_seconds_float;
    j["paper_experiment_evaluations"] = r.paper_evaluations;
  }
  return j;
}

}  // namespace hexgait
