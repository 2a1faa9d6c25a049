// The paper's genetic algorithm's data: its parameters, individuals, generation statistics
// and checkpoint state. The algorithm itself runs as an optimizer of the search driver
// (search/ga_optimizer.h): a small population of genomes, fitness = distance walked,
// roulette-wheel selection, one-point crossover and bit-flip mutation on the 480-bit
// chromosome; every random choice is made on the calling thread from a per-generation stream,
// so results do not depend on how the evaluator runs them.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "eval/evaluator.h"
#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/step_loop.h"
#include "util/param_table.h"

namespace hexgait {

// The paper's GA's own parameters: crossover_rate (probability a child is a one-point crossover
// of two parents), mutation_rate (per-bit flips of a child), initial_mutation_rate (per-bit
// flips of the unoptimised genome that make the initial population; individual 0 is kept as
// is) and elites (the best individuals copied unchanged into the next generation).
extern const ParamTable kGaParams;
// initial_mutation_rate's row, shared by every optimizer that starts, as the GA does, from
// mutants of the unoptimised genome (search/archive_optimizer.h). Constant, so other files'
// tables may copy it while they are initialised.
inline constexpr ParamSpec kInitialMutationRateParam = {
    "initial_mutation_rate",
    false,
    0.02,
    0,
    1,
    "Per-bit flips of the unoptimised genome that make the first children (the GA's initial "
    "population; a repertoire's while no gait stands yet)"};

struct EvolutionParams {
  uint64_t seed = 1;
  int population = 4;    // CMA-ES: its lambda, 0 meaning Hansen's default 4 + 3 ln n
  int generations = 10;  // after the initial population (generation 0)
  // The optimizer's own parameters, by its table (search/optimizers.cc): the GA's
  // (kGaParams above) unless another optimizer's are put in their place (CMA-ES's sigma).
  ParamValues settings = ParamValues::Defaults(kGaParams);
  // Individual 0 of the initial population, and what the others are mutated from; empty: the
  // unoptimised program (every gene 0). Set to start from a known gait (`hexgait adapt`'s GA
  // comparison starts from the intact creature's best).
  std::vector<int8_t> start;
  bool symmetric = false;  // 60 genes shared by mirror springs instead of 120
  int threads = 0;         // 0: all hardware threads
  // Creatures simulated in lock-step per batch (sim/batch_evaluate.h): 0 picks from the
  // population, the thread count and the CPU's vector width; 1 runs the scalar path. The
  // results are the same bits whatever this is.
  int batch_lanes = 0;
  // The lanes' number type. Float needs the explicit Euler integrator and always runs batched;
  // its fitnesses differ from double's by the error `hexgait bench accuracy` reports as
  // euler-float (docs/model.md, "Float lanes").
  Precision precision = Precision::kDouble;
  RunOptions run;
};

struct Individual {
  Genome genome;
  RunResult result;
  double fitness = 0;
};

struct GenerationStats {
  int generation = 0;
  double best = 0, mean = 0, worst = 0;
  int best_index = 0;
  int evaluations = 0;  // fitness evaluations made in this generation
  double seconds = 0;   // wall time of this generation
  int diverged = 0;     // of the evaluations, simulations that diverged (fitness 0; never "fell")
};

struct EvolutionResult {
  std::vector<GenerationStats> history;
  std::optional<Individual> best;  // best ever seen (the elite keeps it in the population)
  int total_evaluations = 0;
};

// The state after a completed generation: enough to continue the run (see checkpoint.h).
struct EvolutionCheckpoint {
  EvolutionParams params;
  int generation = 0;  // last completed generation
  std::vector<Individual> population;
  EvolutionResult so_far;
};

// A generation's best, mean and worst fitness and the index of its first best.
GenerationStats SummariseGeneration(int generation, const std::vector<Individual>& population);

// Checks parameters; throws InputError with a one-line message naming the bad one.
void ValidateEvolutionParams(const EvolutionParams& params);

// The evaluator settings `params` ask for (threads, lanes, precision, run options).
EvaluatorConfig EvaluatorConfigFor(const EvolutionParams& params);

// Decodes the genomes of `individuals[pending[k]]` and evaluates them in one call of
// `evaluator`, filling in their results and fitnesses.
void EvaluatePending(Evaluator& evaluator, const CreatureModel& model, const MotorProgram& program,
                     std::vector<Individual>& individuals, const std::vector<int>& pending,
                     const Progress& on_progress = {});

}  // namespace hexgait
