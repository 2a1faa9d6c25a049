#include "ga/evolution.h"

#include <algorithm>

#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {

GenerationStats SummariseGeneration(int generation, const std::vector<Individual>& population) {
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

const ParamTable kGaParams = {
    {"crossover_rate", false, 0.7, 0, 1, "Probability of one-point crossover"},
    {"mutation_rate", false, 0.01, 0, 1, "Per-bit mutation probability"},
    kInitialMutationRateParam,
    {"elites", true, 1, 0, 100000, "Best individuals kept unchanged each generation"},
};

void ValidateEvolutionParams(const EvolutionParams& p) {
  if (p.population < 2) throw InputError("--population must be at least 2");
  if (p.population > 100000) throw InputError("--population must be at most 100000");
  if (p.generations < 1) throw InputError("--generations must be at least 1");
  if (p.generations > 100000) throw InputError("--generations must be at most 100000");
  CheckParams(kGaParams, p.settings, "ga");
  if (p.settings.Integer("elites") >= p.population) {
    throw InputError("--elites must be in [0, population - 1]");
  }
  CheckEvaluatorConfig(EvaluatorConfigFor(p));
}

EvaluatorConfig EvaluatorConfigFor(const EvolutionParams& params) {
  return EvaluatorConfigOf(params);
}

void EvaluatePending(Evaluator& evaluator, const CreatureModel& model, const MotorProgram& program,
                     std::vector<Individual>& individuals, const std::vector<int>& pending,
                     const Progress& on_progress) {
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

}  // namespace hexgait
