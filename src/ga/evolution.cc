#include "ga/evolution.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "ga/rng.h"
#include "ga/roulette.h"
#include "sim/batch_evaluate.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void Mutate(std::vector<uint8_t>& bits, double rate, Rng& rng) {
  for (uint8_t& bit : bits) {
    if (rng.Bernoulli(rate)) bit ^= 1u;
  }
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

int ResolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

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
  if (p.threads < 0 || p.threads > 1024) throw InputError("--threads must be in [0, 1024]");
  if (p.batch_lanes < 0 || p.batch_lanes > kMaxBatchLanes) {
    std::string message = "--batch-lanes must be in [0, ";
    message += std::to_string(kMaxBatchLanes);
    message += "]";
    throw InputError(message);
  }
  if (p.precision == Precision::kFloat && p.run.integrator != IntegratorKind::kEuler) {
    throw InputError("--precision float needs --integrator euler");
  }
}

std::vector<int> PlanBatches(int pending, int threads, int batch_lanes, Precision precision,
                             bool creature_kernel) {
  if (pending <= 0) return {};
  int lanes = batch_lanes;
  const int per_thread = (pending + threads - 1) / std::max(1, threads);
  if (lanes <= 0 && creature_kernel && precision == Precision::kFloat &&
      per_thread <= kCreatureKernelMaxBatch) {
    lanes = per_thread;
  } else if (lanes <= 0) {
    // Fill vector registers before spreading over threads: a batch narrower than the vector
    // costs about as much per step as a full one (`hexgait bench speed`, lanes rows), so
    // splitting the paper's 3 creatures 2 + 1 over two threads saves little and doubles the
    // CPU time.
    lanes = std::min(kMaxBatchLanes,
                     std::max(NativeBatchLanes(BatchIsa::kAuto, precision), per_thread));
  }
  lanes = std::min(lanes, kMaxBatchLanes);
  const int batches = (pending + lanes - 1) / lanes;
  std::vector<int> sizes(batches, pending / batches);
  for (int b = 0; b < pending % batches; ++b) ++sizes[b];
  return sizes;
}

void EvaluateInParallel(const CreatureModel& model, const MotorProgram& program,
                        const RunOptions& options, std::vector<Individual>& individuals,
                        const std::vector<int>& pending, int threads,
                        const std::function<void(int, int)>& on_progress, int batch_lanes,
                        Precision precision) {
  const int total = static_cast<int>(pending.size());
  const int workers_wanted = ResolveThreadCount(threads);
  // Batches of consecutive pending individuals; the scalar path for other integrators, and for
  // double with --batch-lanes 1. Float always runs batched (it has no scalar path: one lane of
  // the batched kernel), which refuses integrators other than euler.
  const bool batched = precision == Precision::kFloat ||
                       (options.integrator == IntegratorKind::kEuler && batch_lanes != 1);
  const std::vector<int> sizes = batched
                                     ? PlanBatches(total, workers_wanted, batch_lanes, precision,
                                                   CreatureSimulation::Available(model))
                                     : std::vector<int>(total, 1);
  std::vector<int> first(sizes.size() + 1, 0);
  for (size_t b = 0; b < sizes.size(); ++b) first[b + 1] = first[b] + sizes[b];
  const int num_batches = static_cast<int>(sizes.size());

  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  std::mutex progress_mutex;
  std::condition_variable progress;
  int workers_done = 0;  // guarded by progress_mutex
  auto work = [&] {
    for (int b; (b = next.fetch_add(1)) < num_batches && !failed.load();) {
      try {
        if (batched) {
          std::vector<const Genome*> genomes;
          for (int k = first[b]; k < first[b + 1]; ++k) {
            genomes.push_back(&individuals[pending[k]].genome);
          }
          const std::vector<RunResult> results = EvaluateGenomesBatched(
              model, program, genomes, options, 0, BatchIsa::kAuto, precision);
          for (int k = first[b]; k < first[b + 1]; ++k) {
            Individual& ind = individuals[pending[k]];
            ind.result = results[k - first[b]];
            ind.fitness = Fitness(ind.result);
          }
        } else {
          Individual& ind = individuals[pending[first[b]]];
          ind.result = EvaluateGenome(model, program, ind.genome, options);
          ind.fitness = Fitness(ind.result);
        }
      } catch (...) {
        if (!failed.exchange(true)) error = std::current_exception();
      }
      done.fetch_add(sizes[b]);
    }
  };
  const int workers = std::max(1, std::min(workers_wanted, num_batches));
  if (workers == 1) {
    work();
  } else {
    // Every worker evaluates; the calling thread only reports progress, every 100 ms, and
    // returns as soon as the last worker is done. (It used to evaluate too, after reporting
    // until every batch was claimed: with as many batches as threads, that ran them one after
    // the other.)
    std::vector<std::thread> pool;
    for (int t = 0; t < workers; ++t) {
      pool.emplace_back([&] {
        work();
        std::lock_guard<std::mutex> lock(progress_mutex);
        ++workers_done;
        progress.notify_one();
      });
    }
    {
      std::unique_lock<std::mutex> lock(progress_mutex);
      while (workers_done < workers) {
        if (on_progress) {
          lock.unlock();
          on_progress(done.load(), total);
          lock.lock();
        }
        progress.wait_for(lock, std::chrono::milliseconds(100),
                          [&] { return workers_done == workers; });
      }
    }
    for (std::thread& t : pool) t.join();
  }
  if (on_progress) on_progress(total, total);
  if (error) std::rethrow_exception(error);
}

EvolutionResult Evolve(const CreatureModel& model, const MotorProgram& program,
                       const EvolutionParams& params, const EvolutionCallbacks& callbacks,
                       const EvolutionCheckpoint* resume) {
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
        Mutate(bits, params.initial_mutation_rate, rng);
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
          const std::vector<uint8_t> other = b.genome.ToBits();
          const uint32_t cut = 1 + rng.NextBelow(static_cast<uint32_t>(bits.size() - 1));
          std::copy(other.begin() + cut, other.end(), bits.begin() + cut);
        }
        Mutate(bits, params.mutation_rate, rng);
        Individual child{Genome(layout), {}, 0};
        child.genome.FromBits(bits);
        pending.push_back(static_cast<int>(next.size()));
        next.push_back(std::move(child));
      }
      population = std::move(next);
    }
    EvaluateInParallel(model, program, params.run, population, pending, params.threads,
                       callbacks.on_progress, params.batch_lanes, params.precision);
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
