// `hexgait bench speed`'s measurement: ns per creature-step on each path (the naive loop, the
// scalar path, the batched kernel at every lane count in double and float, the float creature
// kernel), the batched kernel on all cores, the flop rate against the core's measured peak, and
// the paper's whole experiment. Every figure is the median of `repeats` timings, taken in
// rounds so the ratios hold on a busy machine; one-core figures are the measuring thread's CPU
// time, all-cores figures wall time.
#pragma once

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "ga/evolution.h"
#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "util/progress.h"

namespace hexgait {

// Flops of one creature-step, counted from the kernel (sim/batch_kernel_impl.h), with a square
// root or a division counted as one flop (they cost far more):
//   per spring 34: difference 3, squared length 5, sqrt 1, 1/L 1, unit vector 3, rate 8
//                  (3 sub, 3 mul, 2 add), magnitude 4, force 3, scatter to both ends 6;
//   per particle 14: weight 1, Euler update 13 (h 1, positions 6, velocities 6);
//   per particle in ground contact 15: normal 3, friction scale 7 (incl. sqrt and div),
//                  normal force 1, friction force 4 (counted for the 6 feet).
inline constexpr int kFlopsPerSpring = 34;
inline constexpr int kFlopsPerParticle = 14;
inline constexpr int kFlopsPerContact = 15;

struct SpeedSettings {
  double seconds = 0.25;  // approximate length of each timing
  int repeats = 5;        // timings per figure; the median is reported
  int threads = 0;        // threads for the all-cores figures; 0: all cores
  // Runs the paper's whole experiment (`hexgait evolve --seed 1`) with `params` and returns its
  // result; empty: the experiment is not timed. (The GA's driver is in src/search, which
  // src/bench does not include: the command hands it in.)
  std::function<EvolutionResult(const EvolutionParams& params)> paper_experiment;
  // Children of a standing gait evaluated as the repertoire evaluates them (stop at the fall),
  // with finished lanes refilled and kept to their batch's end; 0: not measured.
  int repertoire_children = 256;
};

// The one-core paths, each a group of the report (and of its JSON).
enum class SpeedPathKind {
  kNaive,           // the plain array-of-structs Eigen loop
  kScalar,          // the scalar structure-of-arrays path (EvaluateGenome)
  kBatched,         // the batched kernel in double, one row per lane count
  kBatchedFloat,    // the same in float
  kCreatureKernel,  // the float creature kernel, one row per creature count (AVX-512 only)
};

// One path on one core: ns per creature-step, medians.
struct SpeedRow {
  std::string name;
  SpeedPathKind kind = SpeedPathKind::kNaive;
  int creatures = 1;  // creatures one run simulates at once (lanes for the batched kernel)
  double cpu_ns = 0;  // CPU time of the measuring thread
  double wall_ns = 0;
};

struct SpeedReport {
  std::string cpu;         // CpuModel()
  std::string kernel_isa;  // BatchIsaName of the best instruction set
  int native_lanes = 1;    // doubles per vector of that instruction set
  int threads = 1;         // threads of the all-cores figures
  int repeats = 1;
  double steps_per_evaluation = 0;  // creature-steps of one evaluation (1000 time units)

  std::vector<SpeedRow> rows;       // one core, in the order they are printed
  size_t naive = 0, single = 1;     // rows of the naive loop and the scalar path
  size_t best = 0, best_float = 0;  // the fastest batched rows (CPU time), double and float
  int best_lanes = 1, best_lanes_float = 1;
  double all_cores_ns = 0, all_cores_float_ns = 0;  // best lanes x threads, wall time

  int flops_per_creature_step = 0;
  double gflops = 0, gflops_float = 0;            // the best batched rows on one core
  double peak_gflops = 0, peak_gflops_float = 0;  // vector multiply + add on this core
  int sqrt_div_pairs = 0;                         // per creature-step
  double sqrt_div_floor_ns = 0, sqrt_div_floor_float_ns = 0;
  double evaluation_ms = 0, evaluation_ms_float = 0;  // one evaluation, best batched, one core

  // The repertoire's workload, with finished lanes refilled and kept: `children` children (each
  // bit flipped with probability 0.01) of `parents`, stop at the fall, double, `threads`
  // threads. Two workloads: the children of the unoptimised program (a repertoire's first
  // batches) and the children of a standing archive (the rest of it).
  struct RefillWorkload {
    std::string key;      // "unoptimized_children", "archive_children": its JSON keys' suffix
    std::string parents;  // in words
    int children = 0;
    double fell = 0;  // fraction of the children that fell
    double refilled_evals_per_s = 0, kept_evals_per_s = 0;
    double ratio() const { return refilled_evals_per_s / kept_evals_per_s; }
  };
  std::vector<RefillWorkload> refill;  // empty: not measured

  bool paper_experiment_timed = false;
  int paper_evaluations = 0;
  double paper_seconds = 0, paper_seconds_float = 0, paper_seconds_one_at_a_time = 0;
};

// The random genomes every path of MeasureSpeed runs: `count` of them, each gene uniform in
// kGeneMin..kGeneMax, from a fixed stream, so the micro-benchmarks can time exactly its workload.
// Most of them fall, and every one is on its own path.
std::vector<Genome> SpeedGenomes(const CreatureModel& model, const MotorProgram& program,
                                 int count);

// Measures every path on `model` running `program` (SpeedGenomes).
// `note`, when given, hears a line as each stage starts.
SpeedReport MeasureSpeed(const CreatureModel& model, const MotorProgram& program,
                         const SpeedSettings& settings, const LogLine& note = {});

// `hexgait bench speed --json`.
nlohmann::json SpeedReportJson(const SpeedReport& report);

}  // namespace hexgait
