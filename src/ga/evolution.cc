#include "ga/evolution.h"

#include <algorithm>
#include <chrono>

#include "ga/rng.h"
#include "ga/roulette.h"
#include "ga/variation.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

GenerationStats Summarise(int generation, const std::vector<Individual>& population) {
  GenerationStats stats;
  stats.generation = generation;
  stats.best = stats.worst = population[0].fitness;
  double sum = 0;
  for (size_t i = 0; i < population.size(); ++i) {
    const double f = population[i].fitness;
    sum += f;
    if (f > stats.best) {
      stats.best = f;
      stats.best_index = static_cast<int>(i);
    }
    stats.worst = std::min(stats.worst, f);
  }
  stats.mean = sum / static_cast<double>(population.size());
  return stats;
}

// Indices sorted by fitness, best first; ties keep the lower index first.
std::vector<int> Ranking(const std::vector<Individual>& population) {
  std::vector<int> order(population.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return population[a].fitness > population[b].fitness; });
  return order;
}

}  // namespace

void ValidateEvolutionParams(const EvolutionParams& p) {
  if (p.population < 2) throw InputError("--population must be at least 2");
  if (p.population > 100000) throw InputError("--population must be at most 100000");
  if (p.generations < 1) throw InputError("--generations must be at least 1");
  if (p.generations > 100000) throw InputError("--generations must be at most 100000");
  if (!(p.crossover_rate >= 0 && p.crossover_rate <= 1)) {
    throw InputError("--crossover-rate must be in [0, 1]");
  }
  if (!(p.mutation_rate >= 0 && p.mutation_rate <= 1)) {
    throw InputError("--mutation-rate must be in [0, 1]");
  }
  if (!(p.initial_mutation_rate >= 0 && p.initial_mutation_rate <= 1)) {
    throw InputError("--initial-mutation-rate must be in [0, 1]");
  }
  if (p.elites < 0 || p.elites >= p.population) {
    throw InputError("--elites must be in [0, population - 1]");
  }
  CheckEvaluatorConfig(EvaluatorConfigFor(p));
}

EvaluatorConfig EvaluatorConfigFor(const EvolutionParams& params) {
  return EvaluatorConfigOf(params);
}

void EvaluatePending(Evaluator& evaluator, const CreatureModel& model, const MotorProgram& program,
                     std::vector<Individual>& individuals, const std::vector<int>& pending,
                     const ProgressFn& on_progress) {
  const RestLengthTable geometric = GeometricRestLengths(model, program);
  std::vector<RestLengthTable> tables;
  tables.reserve(pending.size());
  for (int i : pending)
    tables.push_back(PerturbedRestLengths(geometric, model, program, individuals[i].genome));
  const std::vector<RunResult> results = evaluator.Evaluate(tables, on_progress);
  for (size_t k = 0; k < pending.size(); ++k) {
    Individual& ind = individuals[pending[k]];
    ind.result = results[k];
    ind.fitness = Fitness(ind.result);
  }
}

EvolutionResult Evolve(const CreatureModel& model, const MotorProgram& program,
                       const EvolutionParams& params, const EvolutionCallbacks& callbacks,
                       const EvolutionCheckpoint* resume) {
  ValidateEvolutionParams(params);
  const auto evaluator = MakeLocalEvaluator(model, program, EvaluatorConfigFor(params));
  return Evolve(model, program, params, *evaluator, callbacks, resume);
}

EvolutionResult Evolve(const CreatureModel& model, const MotorProgram& program,
                       const EvolutionParams& params, Evaluator& evaluator,
                       const EvolutionCallbacks& callbacks, const EvolutionCheckpoint* resume) {
  ValidateEvolutionParams(params);
  const auto layout = MakeGenomeLayout(model, program, params.symmetric);
  EvolutionResult out;

  // Generation 0: the unoptimised program, plus mutated copies of it.
  std::vector<Individual> population;
  int first_generation = 0;
  if (resume) {
    population = resume->population;
    out = resume->so_far;
    first_generation = resume->generation + 1;
  } else {
    Rng rng = Rng::ForStream(params.seed, 0);
    for (int i = 0; i < params.population; ++i) {
      Individual ind{Genome(layout), {}, 0};
      if (i > 0) {
        std::vector<uint8_t> bits = ind.genome.ToBits();
        MutateBits(bits, params.initial_mutation_rate, rng);
        ind.genome.FromBits(bits);
      }
      population.push_back(std::move(ind));
    }
  }

  for (int generation = first_generation; generation <= params.generations; ++generation) {
    const auto start = Clock::now();
    std::vector<int> pending;
    if (generation == 0) {
      for (int i = 0; i < params.population; ++i) pending.push_back(i);
    } else {
      // Breed generation `generation` from the previous population.
      Rng rng = Rng::ForStream(params.seed, static_cast<uint64_t>(generation));
      const std::vector<int> ranking = Ranking(population);
      std::vector<double> weights;
      for (const Individual& ind : population) weights.push_back(ind.fitness);
      std::vector<Individual> next;
      for (int e = 0; e < params.elites; ++e) next.push_back(population[ranking[e]]);
      while (static_cast<int>(next.size()) < params.population) {
        const Individual& a = population[RouletteSelect(weights, rng.NextDouble())];
        const Individual& b = population[RouletteSelect(weights, rng.NextDouble())];
        std::vector<uint8_t> bits = a.genome.ToBits();
        if (rng.Bernoulli(params.crossover_rate)) {
          CrossOver(bits, b.genome.ToBits(), rng);
        }
        MutateBits(bits, params.mutation_rate, rng);
        Individual child{Genome(layout), {}, 0};
        child.genome.FromBits(bits);
        pending.push_back(static_cast<int>(next.size()));
        next.push_back(std::move(child));
      }
      population = std::move(next);
    }
    EvaluatePending(evaluator, model, program, population, pending, callbacks.on_progress);
    GenerationStats stats = Summarise(generation, population);
    stats.evaluations = static_cast<int>(pending.size());
    stats.seconds = SecondsSince(start);
    out.total_evaluations += stats.evaluations;
    if (!out.best || population[stats.best_index].fitness > out.best->fitness) {
      out.best = population[stats.best_index];
    }
    out.history.push_back(stats);
    if (callbacks.on_generation) callbacks.on_generation(stats, population);
    if (callbacks.on_checkpoint) {
      callbacks.on_checkpoint(EvolutionCheckpoint{params, generation, population, out});
    }
  }
  return out;
}

}  // namespace hexgait
