// The paper's GA, one generation per ask and tell: roulette-wheel parents, one-point crossover,
// bit-flip mutation and elites (docs/model.md). Every random choice of generation g is drawn
// from the stream (seed, g) when it is asked for, so a run resumed from the checkpoint of any
// generation gives the same bits as one never interrupted, and no generator state is saved.
#include "search/ga_optimizer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "ga/checkpoint.h"
#include "ga/rng.h"
#include "ga/roulette.h"
#include "ga/variation.h"
#include "search/search_driver.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"

namespace hexgait {

extern const OptimizerKind kGaOptimizer;

namespace {

// Indices sorted by fitness, best first; ties keep the lower index first.
std::vector<int> Ranking(const std::vector<Individual>& population) {
  std::vector<int> order(population.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return population[a].fitness > population[b].fitness; });
  return order;
}

class GaOptimizer final : public GenerationalOptimizer {
 public:
  GaOptimizer(const SearchScene& scene, const EvolutionParams& params)
      : params_(params),
        layout_(MakeGenomeLayout(scene.model, scene.program, params.symmetric)),
        step_(scene.program.gene_length_step),
        fingerprint_(SceneFingerprint(scene.model, scene.program)),
        creature_(scene.creature),
        damage_(scene.model.damage) {
    ValidateEvolutionParams(params_);
    crossover_rate_ = params_.settings.Get("crossover_rate");
    mutation_rate_ = params_.settings.Get("mutation_rate");
    initial_mutation_rate_ = params_.settings.Get("initial_mutation_rate");
    elites_ = params_.settings.Integer("elites");
    if (!params_.start.empty() && static_cast<int>(params_.start.size()) != layout_->num_genes()) {
      throw InputError("the GA's start genome has " + std::to_string(params_.start.size()) +
                       " genes; this creature's genome has " +
                       std::to_string(layout_->num_genes()));
    }
  }
  GaOptimizer(const SearchScene& scene, const EvolutionCheckpoint& c)
      : GaOptimizer(scene, c.params) {
    generation_ = c.generation;
    population_ = c.population;
    result_ = c.so_far;
  }

  const Candidates& Ask() override {
    if (asked_) return candidates_;
    start_ = Clock::now();
    next_.clear();
    pending_.clear();
    const int generation = generation_ + 1;
    if (generation == 0) {
      // The unoptimised program, plus mutated copies of it.
      Rng rng = Rng::ForStream(params_.seed, 0);
      for (int i = 0; i < params_.population; ++i) {
        Individual ind{Genome(layout_), {}, 0};
        for (size_t g = 0; g < params_.start.size(); ++g) {
          ind.genome.set_gene(static_cast<int>(g), params_.start[g]);
        }
        if (i > 0) {
          std::vector<uint8_t> bits = ind.genome.ToBits();
          MutateBits(bits, initial_mutation_rate_, rng);
          ind.genome.FromBits(bits);
        }
        pending_.push_back(i);
        next_.push_back(std::move(ind));
      }
    } else {
      // Breed generation `generation` from the previous population.
      Rng rng = Rng::ForStream(params_.seed, static_cast<uint64_t>(generation));
      const std::vector<int> ranking = Ranking(population_);
      std::vector<double> weights;
      for (const Individual& ind : population_) weights.push_back(ind.fitness);
      for (int e = 0; e < elites_; ++e) next_.push_back(population_[ranking[e]]);
      while (static_cast<int>(next_.size()) < params_.population) {
        const Individual& a = population_[RouletteSelect(weights, rng.NextDouble())];
        const Individual& b = population_[RouletteSelect(weights, rng.NextDouble())];
        std::vector<uint8_t> bits = a.genome.ToBits();
        if (rng.Bernoulli(crossover_rate_)) CrossOver(bits, b.genome.ToBits(), rng);
        MutateBits(bits, mutation_rate_, rng);
        Individual child{Genome(layout_), {}, 0};
        child.genome.FromBits(bits);
        pending_.push_back(static_cast<int>(next_.size()));
        next_.push_back(std::move(child));
      }
    }
    const int dims = layout_->num_genes();
    candidates_.dims = dims;
    candidates_.offsets.assign(pending_.size() * static_cast<size_t>(dims), 0.0);
    for (size_t k = 0; k < pending_.size(); ++k) {
      const Genome& genome = next_[static_cast<size_t>(pending_[k])].genome;
      for (int g = 0; g < dims; ++g) {
        candidates_.offsets[k * static_cast<size_t>(dims) + static_cast<size_t>(g)] =
            genome.Offset(g, step_);
      }
    }
    asked_ = true;
    return candidates_;
  }

  void Tell(const std::vector<RunResult>& results) override {
    if (!asked_) throw InputError("tell: no batch was asked for");
    if (results.size() != pending_.size()) {
      throw InputError("tell: " + std::to_string(results.size()) + " results for " +
                       std::to_string(pending_.size()) + " candidates");
    }
    for (size_t k = 0; k < pending_.size(); ++k) {
      Individual& ind = next_[static_cast<size_t>(pending_[k])];
      ind.result = results[k];
      ind.fitness = Fitness(ind.result);
    }
    population_ = std::move(next_);
    next_.clear();
    ++generation_;
    GenerationStats stats = SummariseGeneration(generation_, population_);
    stats.evaluations = static_cast<int>(pending_.size());
    for (const RunResult& r : results) stats.diverged += r.diverged ? 1 : 0;
    stats.seconds = SecondsSince(start_);
    result_.total_evaluations += stats.evaluations;
    if (!result_.best || population_[stats.best_index].fitness > result_.best->fitness) {
      result_.best = population_[stats.best_index];
    }
    result_.history.push_back(stats);
    if (generation_ == 0) unoptimized_ = population_[0].result;
    first_new_ = generation_ == 0 ? 0 : static_cast<size_t>(elites_);
    asked_ = false;
  }

  bool Done() const override { return generation_ >= params_.generations; }
  long long evaluations() const override { return result_.total_evaluations; }
  long long budget() const override {
    return params_.population +
           static_cast<long long>(params_.generations) * (params_.population - elites_);
  }
  std::string Position() const override {
    char text[64];
    std::snprintf(text, sizeof text, "after generation %d of %d", generation_, params_.generations);
    return text;
  }
  std::string Save() const override {
    return FormatCheckpoint(GaCheckpointOf(*this), fingerprint_, creature_, damage_);
  }
  const std::shared_ptr<const GenomeLayout>& layout() const override { return layout_; }

  const EvolutionResult& result() const override { return result_; }
  const std::vector<Individual>& generation() const override { return population_; }
  size_t first_new() const override { return first_new_; }
  const EvolutionParams& params() const override { return params_; }
  const RunResult* unoptimized() const override { return unoptimized_ ? &*unoptimized_ : nullptr; }
  const OptimizerKind& kind() const override { return kGaOptimizer; }
  std::string Describe() const override {
    char text[160];
    std::snprintf(text, sizeof text,
                  "the paper's GA: population %d, %d generations, seed %llu, %d genes (%d bits)",
                  params_.population, params_.generations,
                  static_cast<unsigned long long>(params_.seed), layout_->num_genes(),
                  layout_->num_bits());
    return text;
  }

  int last_generation() const { return generation_; }

 private:
  EvolutionParams params_;
  double crossover_rate_ = 0, mutation_rate_ = 0, initial_mutation_rate_ = 0;  // its settings
  int elites_ = 0;
  std::shared_ptr<const GenomeLayout> layout_;
  double step_;
  uint64_t fingerprint_;
  std::string creature_;
  std::string damage_;  // the creature's --damage, recorded beside it

  int generation_ = -1;  // last told
  std::vector<Individual> population_;
  EvolutionResult result_;
  std::optional<RunResult> unoptimized_;
  size_t first_new_ = 0;

  bool asked_ = false;
  std::vector<Individual> next_;
  std::vector<int> pending_;
  Candidates candidates_;
  Clock::time_point start_;
};

std::unique_ptr<GenerationalOptimizer> StartGa(const SearchScene& scene,
                                               const EvolutionParams& params) {
  return MakeGaOptimizer(scene, params);
}

std::unique_ptr<GenerationalOptimizer> ResumeGa(const SearchScene& scene, const std::string& text,
                                                const std::string& source, bool* unchecked) {
  return MakeGaOptimizer(scene,
                         ParseCheckpoint(text, source, scene.model, scene.program, unchecked));
}

}  // namespace

const OptimizerKind kGaOptimizer = {
    "ga",
    "the paper's genetic algorithm (4-bit genes, roulette wheel, elites)",
    "hexgait evolve checkpoint",
    /*default_population=*/4,
    &kGaParams,
    StartGa,
    ResumeGa};

std::unique_ptr<GenerationalOptimizer> MakeGaOptimizer(const SearchScene& scene,
                                                       const EvolutionParams& params) {
  return std::make_unique<GaOptimizer>(scene, params);
}

std::unique_ptr<GenerationalOptimizer> MakeGaOptimizer(const SearchScene& scene,
                                                       const EvolutionCheckpoint& checkpoint) {
  return std::make_unique<GaOptimizer>(scene, checkpoint);
}

EvolutionCheckpoint GaCheckpointOf(const GenerationalOptimizer& ga) {
  const auto& self = dynamic_cast<const GaOptimizer&>(ga);
  return EvolutionCheckpoint{ga.params(), self.last_generation(), ga.generation(), ga.result()};
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
  const SearchScene scene{model, program, ""};
  std::unique_ptr<GenerationalOptimizer> ga =
      resume ? MakeGaOptimizer(scene, *resume) : MakeGaOptimizer(scene, params);
  SearchHooks hooks;
  hooks.on_progress = callbacks.on_progress;
  hooks.after_tell = [&] {
    if (callbacks.on_generation)
      callbacks.on_generation(ga->result().history.back(), ga->generation());
    if (callbacks.on_checkpoint) callbacks.on_checkpoint(GaCheckpointOf(*ga));
  };
  RunSearch(*ga, evaluator, CandidateDecoder(model, program, ga->layout()), hooks);
  return ga->result();
}

}  // namespace hexgait
