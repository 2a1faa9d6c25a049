#include "ga/map_elites.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ga/rng.h"
#include "ga/variation.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {

Archive::Archive(int dims, int bins) : dims_(dims), bins_(bins) {
  long long cells = 1;
  for (int d = 0; d < dims; ++d) cells *= bins;
  cells_.resize(static_cast<size_t>(cells));
}

int Archive::CellOf(const double* behaviour) const {
  int cell = 0;
  for (int d = 0; d < dims_; ++d) {
    // A NaN coordinate lands in bin 0 rather than anywhere undefined.
    const double scaled = std::floor(behaviour[d] * bins_);
    const int bin = scaled >= 0 ? static_cast<int>(std::min<double>(scaled, bins_ - 1)) : 0;
    cell = cell * bins_ + bin;
  }
  return cell;
}

void Archive::BinsOf(int cell, int* bins) const {
  for (int d = dims_ - 1; d >= 0; --d) {
    bins[d] = cell % bins_;
    cell /= bins_;
  }
}

bool Archive::Offer(int cell, Elite&& candidate) {
  std::optional<Elite>& slot = cells_[static_cast<size_t>(cell)];
  if (slot && !(candidate.fitness > slot->fitness)) return false;
  if (!slot) filled_.push_back(cell);
  slot = std::move(candidate);
  return true;
}

double Archive::QdScore() const {
  double sum = 0;
  for (int cell : filled_) sum += std::max(0.0, at(cell)->fitness);
  return sum;
}

const Elite* Archive::Best() const {
  const Elite* best = nullptr;
  int best_cell = 0;
  for (int cell : filled_) {
    const Elite& e = *at(cell);
    if (!best || e.fitness > best->fitness || (e.fitness == best->fitness && cell < best_cell)) {
      best = &e;
      best_cell = cell;
    }
  }
  return best;
}

void ValidateMapElitesParams(const MapElitesParams& p, const CreatureModel& model) {
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(p.descriptor);
  if (p.evaluations < 1 || p.evaluations > 100000000) {
    throw InputError("--evaluations must be in [1, 100000000]");
  }
  if (p.batch < 1 || p.batch > 100000) throw InputError("--batch must be in [1, 100000]");
  if (p.bins < 1 || p.bins > 100) throw InputError("--bins must be in [1, 100]");
  const double cells =
      std::pow(static_cast<double>(p.bins), static_cast<double>(descriptor.axes(model).size()));
  if (cells > static_cast<double>(kMaxArchiveCells)) {
    throw InputError("--bins " + std::to_string(p.bins) + " gives " +
                     std::to_string(descriptor.axes(model).size()) + "-dimensional '" +
                     p.descriptor + "' more than " + std::to_string(kMaxArchiveCells) + " cells");
  }
  for (const auto& [rate, flag] : {std::pair{p.crossover_rate, "--crossover-rate"},
                                   std::pair{p.mutation_rate, "--mutation-rate"},
                                   std::pair{p.initial_mutation_rate, "--initial-mutation-rate"}}) {
    if (!(rate >= 0 && rate <= 1)) throw InputError(std::string(flag) + " must be in [0, 1]");
  }
  CheckEvaluatorConfig(EvaluatorConfigFor(p));
}

EvaluatorConfig EvaluatorConfigFor(const MapElitesParams& params) {
  return EvaluatorConfigOf(params);
}

MapElitesState StartMapElites(const MapElitesParams& params, const CreatureModel& model) {
  ValidateMapElitesParams(params, model);
  MapElitesState state;
  state.params = params;
  const int dims = static_cast<int>(FindBehaviourDescriptor(params.descriptor).axes(model).size());
  state.archive = Archive(dims, params.bins);
  return state;
}

bool IsStandingGait(const RunResult& result) {
  return !result.fell && !result.diverged && std::isfinite(result.distance);
}

bool OfferToArchive(Archive& archive, const BehaviourDescriptor& descriptor,
                    const CreatureModel& model, Elite&& candidate) {
  if (!IsStandingGait(candidate.result)) return false;
  double behaviour[kMaxLegs * 2];
  descriptor.measure(model, candidate.result, behaviour);
  return archive.Offer(archive.CellOf(behaviour), std::move(candidate));
}

ArchiveStats StatsOf(const Archive& archive, long long evaluations, double seconds) {
  ArchiveStats stats;
  stats.evaluations = evaluations;
  stats.filled = static_cast<int>(archive.filled().size());
  stats.qd_score = archive.QdScore();
  const Elite* best = archive.Best();
  stats.best = best ? best->fitness : 0;
  stats.seconds = seconds;
  return stats;
}

void RunMapElites(const CreatureModel& model, const MotorProgram& program, Evaluator& evaluator,
                  MapElitesState& state, const MapElitesCallbacks& callbacks) {
  const MapElitesParams& params = state.params;
  ValidateMapElitesParams(params, model);
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(params.descriptor);
  const auto layout = MakeGenomeLayout(model, program, params.symmetric);
  const RestLengthTable geometric = GeometricRestLengths(model, program);
  const Genome plain(layout);
  while (state.evaluations < params.evaluations) {
    const auto start = std::chrono::steady_clock::now();
    const int count =
        static_cast<int>(std::min<long long>(params.batch, params.evaluations - state.evaluations));
    Rng rng = Rng::ForStream(params.seed, static_cast<uint64_t>(state.batches));
    const std::vector<int>& filled = state.archive.filled();
    std::vector<Genome> children;
    children.reserve(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
      std::vector<uint8_t> bits;
      if (filled.empty()) {
        // Nothing stands yet: search around the paper's unoptimised program, as the GA starts.
        bits = plain.ToBits();
        if (state.evaluations + k > 0) MutateBits(bits, params.initial_mutation_rate, rng);
      } else {
        const auto pick = [&] {
          return *state.archive.at(filled[rng.NextBelow(static_cast<uint32_t>(filled.size()))]);
        };
        bits = pick().genome.ToBits();
        if (rng.Bernoulli(params.crossover_rate)) CrossOver(bits, pick().genome.ToBits(), rng);
        MutateBits(bits, params.mutation_rate, rng);
      }
      Genome child(layout);
      child.FromBits(bits);
      children.push_back(std::move(child));
    }
    std::vector<RestLengthTable> tables;
    tables.reserve(children.size());
    for (const Genome& child : children) {
      tables.push_back(PerturbedRestLengths(geometric, model, program, child));
    }
    const std::vector<RunResult> results = evaluator.Evaluate(tables, callbacks.on_progress);
    for (int k = 0; k < count; ++k) {
      const RunResult& r = results[static_cast<size_t>(k)];
      OfferToArchive(state.archive, descriptor, model,
                     Elite{std::move(children[static_cast<size_t>(k)]), r, Fitness(r),
                           state.evaluations + k + 1});
    }
    state.evaluations += count;
    ++state.batches;
    state.history.push_back(
        StatsOf(state.archive, state.evaluations,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
    if (callbacks.on_batch) callbacks.on_batch(state);
  }
}

std::vector<int> ChooseShowcase(const Archive& archive, const BehaviourDescriptor& descriptor,
                                const CreatureModel& model, int count) {
  std::vector<int> chosen;
  const Elite* best = archive.Best();
  if (!best || count < 1) return chosen;
  std::vector<double> distances;
  for (int cell : archive.filled()) distances.push_back(archive.at(cell)->fitness);
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  const double median = distances[distances.size() / 2];
  const size_t dims = static_cast<size_t>(archive.dims());
  const auto behaviour = [&](int cell) {
    std::vector<double> b(static_cast<size_t>(kMaxLegs * 2));
    descriptor.measure(model, archive.at(cell)->result, b.data());
    b.resize(dims);
    return b;
  };
  std::vector<int> candidates;
  for (int cell : archive.filled()) {
    if (archive.at(cell)->fitness >= median) candidates.push_back(cell);
  }
  std::sort(candidates.begin(), candidates.end());
  int first = candidates.front();
  for (int cell : candidates) {
    if (archive.at(cell)->fitness > archive.at(first)->fitness) first = cell;
  }
  chosen.push_back(first);
  std::vector<std::vector<double>> chosen_behaviour = {behaviour(first)};
  while (static_cast<int>(chosen.size()) < count) {
    int next = -1;
    double next_gap = -1;
    for (int cell : candidates) {
      if (std::find(chosen.begin(), chosen.end(), cell) != chosen.end()) continue;
      const std::vector<double> b = behaviour(cell);
      double gap = INFINITY;
      for (const std::vector<double>& c : chosen_behaviour) {
        double l1 = 0;
        for (size_t d = 0; d < dims; ++d) l1 += std::abs(b[d] - c[d]);
        gap = std::min(gap, l1);
      }
      if (gap > next_gap) {
        next = cell;
        next_gap = gap;
      }
    }
    if (next < 0) break;
    chosen.push_back(next);
    chosen_behaviour.push_back(behaviour(next));
  }
  return chosen;
}

}  // namespace hexgait
