#include "ga/map_elites.h"

#include <algorithm>
#include <cmath>

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
  if (p.confirm_in_double && p.precision != Precision::kFloat) {
    throw InputError("confirming admissions in double needs --precision float");
  }
  CheckEvaluatorConfig(EvaluatorConfigFor(p));
}

std::string PrecisionText(const MapElitesParams& params) {
  std::string text = PrecisionName(params.precision);
  if (params.confirm_in_double) text += ", admissions confirmed in double";
  return text;
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

bool WouldEnterArchive(const Archive& archive, const BehaviourDescriptor& descriptor,
                       const CreatureModel& model, const RunResult& result) {
  if (!IsStandingGait(result)) return false;
  double behaviour[kMaxLegs * 2];
  descriptor.measure(model, result, behaviour);
  const std::optional<Elite>& incumbent = archive.at(archive.CellOf(behaviour));
  return !incumbent || Fitness(result) > incumbent->fitness;
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

std::vector<int> ChooseShowcase(const Archive& archive, const BehaviourDescriptor& descriptor,
                                const CreatureModel& model, int count) {
  std::vector<int> chosen;
  const Elite* best = archive.Best();
  if (!best || count < 1) return chosen;
  std::vector<double> distances;
  for (int cell : archive.filled()) distances.push_back(archive.at(cell)->fitness);
  // The upper half by distance (the upper median, not util/median.h's mean of the middle two:
  // the showcase of every archive written so far depends on it).
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
