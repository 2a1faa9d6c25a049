// CMA-MAE (M. Fontaine and S. Nikolaidis, "Covariance Matrix Adaptation MAP-Annealing",
// GECCO 2023) as an archive optimizer: a few CMA-ES emitters (search/cma_distribution.h), each
// ranking its children by how far they beat their cell's threshold, and a threshold per cell
// that moves towards every gait beating it by the learning rate alpha (1: CMA-ME's "improve the
// elite"; 0: never, so the emitters only climb the distance). The archive of elites that the
// report, replay and adaptation read is the same as MAP-Elites' (ga/map_elites.h): a gait enters
// when it stands the test and walks farther than the cell's elite.
//
// Choices of this implementation (docs/model.md, "CMA-MAE on 4-bit genes"):
// - The emitters search the genes as real numbers in gene steps; a child is its sample rounded
//   to the nearest gene in [-8, 7], so its elites are the same discrete genomes as MAP-Elites'.
//   Samples are bounded to [-8.5, 7.5], and the update uses the samples.
// - A child that fell ranks below every standing one, by how long it stood; one that diverged
//   last. So while nothing stands yet the emitters learn to stand, as the GA does from the
//   paper's falling program.
// - Improvements are measured against the thresholds as the batch began; the thresholds then
//   move child by child, in order.
// - An emitter restarts, at one elite picked uniformly (or the unoptimised program while the
//   archive is empty), when none of its children beat a threshold while the archive holds
//   elites, or when its largest deviation fell below 0.05 gene steps (every child would round
//   to the same genome).
//
// Every random number of batch b comes from the stream (seed, b) in a fixed order (for each
// emitter: its restart, then its samples), so archives do not depend on threads, lanes or
// ranks, and "algorithm_state" (each emitter's distribution, the thresholds) resumes to the
// same bits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ga/checkpoint_json.h"
#include "search/archive_optimizer.h"
#include "search/cma_distribution.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {
namespace {

using nlohmann::json;
using Vector = CmaDistribution::Vector;

const ParamTable kParams = {
    {"emitters", true, 25, 1, 1000,
     "CMA-ES emitters; each makes batch / emitters children per batch (batch >= 2 x emitters)"},
    {"sigma", false, 2.0, 0.01, 16, "Each emitter's step size at a (re)start, in gene steps"},
    {"learning_rate", false, 0.1, 0, 1,
     "alpha: how far a cell's threshold moves towards a gait that beats it (1: CMA-ME)"},
    {"threshold_min", false, 0, -1000, 1000,
     "A cell's threshold before any gait beat it: the distance that counts as an improvement"},
};

constexpr double kLowestSample = kGeneMin - 0.5;
constexpr double kHighestSample = kGeneMax + 0.5;
constexpr double kStuckDeviation = 0.05;  // gene steps: every sample rounds to the mean's genes

// A child's merit for its emitter's ranking: standing children by how far they beat their
// cell's threshold, then fallen ones by how long they stood, then diverged ones.
struct Merit {
  int tier = 0;  // 2 standing, 1 fell, 0 diverged
  double value = 0;
  bool operator>(const Merit& o) const { return tier != o.tier ? tier > o.tier : value > o.value; }
};

struct Emitter {
  std::unique_ptr<CmaDistribution> cma;  // null: starts at the next batch
  int generation = 0;                    // updates since the last (re)start
  long long restarts = 0;
};

class CmaMae final : public ArchiveOptimizer {
 public:
  CmaMae(const ArchiveOptimizerKind& kind, const SearchScene& scene, MapElitesState state)
      : ArchiveOptimizer(kind, scene, std::move(state)),
        emitters_(static_cast<size_t>(state_.params.settings.Integer("emitters"))),
        sigma_(state_.params.settings.Get("sigma")),
        alpha_(state_.params.settings.Get("learning_rate")),
        threshold_min_(state_.params.settings.Get("threshold_min")),
        thresholds_(static_cast<size_t>(state_.archive.cells()), threshold_min_) {
    const int count = static_cast<int>(emitters_.size());
    if (state_.params.batch < 2 * count) {
      throw InputError("--batch must be at least 2 x --emitters for cma-mae (" +
                       std::to_string(2 * count) + ")");
    }
    if (!state_.algorithm_state.is_null()) Load(state_.algorithm_state);
  }

 private:
  // Children of emitter e in a full batch (the last batch may give each fewer).
  int LambdaOf(size_t e, int batch) const {
    const int count = static_cast<int>(emitters_.size());
    return batch / count + (static_cast<int>(e) < batch % count ? 1 : 0);
  }

  std::vector<Genome> MakeChildren(int count, Rng& rng) override {
    const int dims = layout_->num_genes();
    samples_.clear();
    owners_.clear();
    std::vector<Genome> children;
    for (size_t e = 0; e < emitters_.size(); ++e) {
      Emitter& emitter = emitters_[e];
      const int lambda = LambdaOf(e, count);
      if (lambda == 0) continue;
      if (!emitter.cma) Start(emitter, LambdaOf(e, state_.params.batch), rng);
      for (int k = 0; k < lambda; ++k) {
        Vector x = emitter.cma->Sample(rng, kLowestSample, kHighestSample);
        Genome child(layout_);
        for (int g = 0; g < dims; ++g) {
          const double gene = std::clamp(std::nearbyint(x[g]), double{kGeneMin}, double{kGeneMax});
          child.set_gene(g, static_cast<int>(gene));
        }
        children.push_back(std::move(child));
        samples_.push_back(std::move(x));
        owners_.push_back(e);
      }
    }
    return children;
  }

  // A (re)start at an elite picked uniformly, or at the unoptimised program while none stands.
  void Start(Emitter& emitter, int lambda, Rng& rng) const {
    Vector mean = Vector::Zero(layout_->num_genes());
    const std::vector<int>& filled = state_.archive.filled();
    if (!filled.empty()) {
      const Elite& elite =
          *state_.archive.at(filled[rng.NextBelow(static_cast<uint32_t>(filled.size()))]);
      for (int g = 0; g < layout_->num_genes(); ++g) mean[g] = elite.genome.gene(g);
    }
    emitter.cma = std::make_unique<CmaDistribution>(lambda, mean, sigma_);
  }

  void Learn(const std::vector<RunResult>& results) override {
    // Every child's merit against the thresholds as the batch began...
    std::vector<Merit> merit(results.size());
    std::vector<int> cell(results.size(), -1);
    for (size_t k = 0; k < results.size(); ++k) {
      const RunResult& r = results[k];
      if (r.diverged || !std::isfinite(r.distance)) continue;  // tier 0
      if (!IsStandingGait(r)) {
        merit[k] = {1, r.fall_time};
        continue;
      }
      double behaviour[kMaxLegs * 2];
      descriptor_.measure(model_, r, behaviour);
      cell[k] = state_.archive.CellOf(behaviour);
      merit[k] = {2, Fitness(r) - thresholds_[static_cast<size_t>(cell[k])]};
    }
    // ...then the thresholds, child by child.
    for (size_t k = 0; k < results.size(); ++k) {
      if (cell[k] < 0) continue;
      double& threshold = thresholds_[static_cast<size_t>(cell[k])];
      const double f = Fitness(results[k]);
      if (f > threshold) threshold = (1 - alpha_) * threshold + alpha_ * f;
    }
    for (size_t e = 0; e < emitters_.size(); ++e) {
      std::vector<size_t> mine;
      for (size_t k = 0; k < owners_.size(); ++k) {
        if (owners_[k] == e) mine.push_back(k);
      }
      if (mine.empty()) continue;
      std::stable_sort(mine.begin(), mine.end(),
                       [&](size_t a, size_t b) { return merit[a] > merit[b]; });
      const bool improved = merit[mine.front()].tier == 2 && merit[mine.front()].value > 0;
      Emitter& emitter = emitters_[e];
      bool healthy = true;
      if (static_cast<int>(mine.size()) >= emitter.cma->mu()) {
        std::vector<const double*> best_first;
        for (size_t k : mine) best_first.push_back(samples_[k].data());
        healthy = emitter.cma->Update(best_first, ++emitter.generation);
      }
      const bool stuck = !healthy || emitter.cma->LargestDeviation() < kStuckDeviation;
      if (stuck || (!improved && !state_.archive.filled().empty())) {
        emitter.cma.reset();
        emitter.generation = 0;
        ++emitter.restarts;
      }
    }
  }

  json AlgorithmState() const override {
    json emitters = json::array();
    for (const Emitter& emitter : emitters_) {
      json e = {{"generation", emitter.generation}, {"restarts", emitter.restarts}};
      if (emitter.cma) {
        json distribution;
        emitter.cma->Save(distribution);
        e["distribution"] = distribution;
      } else {
        e["distribution"] = nullptr;
      }
      emitters.push_back(e);
    }
    // Only the cells whose threshold moved, in cell order.
    json cells = json::array(), values = json::array();
    for (size_t c = 0; c < thresholds_.size(); ++c) {
      if (thresholds_[c] == threshold_min_) continue;
      cells.push_back(c);
      values.push_back(Number(thresholds_[c]));
    }
    return {{"emitters", emitters}, {"threshold_cells", cells}, {"threshold_values", values}};
  }

  void Load(const json& saved) {
    const JsonReader r(saved, "the archive", "algorithm_state");
    r.RequireOnlyKeys({"emitters", "threshold_cells", "threshold_values"});
    const JsonReader emitters = r.Child("emitters");
    if (emitters.ArraySize() != emitters_.size()) {
      emitters.Fail("must have one entry per emitter (" + std::to_string(emitters_.size()) + ")");
    }
    for (size_t e = 0; e < emitters_.size(); ++e) {
      const JsonReader entry = emitters.At(e);
      entry.RequireOnlyKeys({"generation", "restarts", "distribution"});
      Emitter& emitter = emitters_[e];
      emitter.generation = entry.Integer("generation");
      emitter.restarts = ReadInteger64(entry, "restarts");
      if (emitter.generation < 0 || emitter.restarts < 0) {
        entry.Fail("'generation' and 'restarts' must not be negative");
      }
      if (entry.value().at("distribution").is_null()) continue;
      const int lambda = LambdaOf(e, state_.params.batch);
      emitter.cma =
          std::make_unique<CmaDistribution>(lambda, Vector::Zero(layout_->num_genes()), sigma_);
      emitter.cma->Load(entry.Child("distribution"));
    }
    const JsonReader cells = r.Child("threshold_cells");
    const JsonReader values = r.Child("threshold_values");
    if (cells.ArraySize() != values.ArraySize()) {
      r.Fail("'threshold_cells' and 'threshold_values' must have the same length");
    }
    long long last = -1;
    for (size_t i = 0; i < cells.ArraySize(); ++i) {
      const long long c = cells.At(i).AsInteger();
      if (c <= last || c >= state_.archive.cells()) {
        cells.Fail("must be increasing cells of the archive");
      }
      const double v = values.At(i).AsNumber();
      if (!std::isfinite(v) || v < threshold_min_) {
        values.Fail("must be finite and at least --threshold-min");
      }
      thresholds_[static_cast<size_t>(c)] = v;
      last = c;
    }
  }

  std::vector<Emitter> emitters_;
  double sigma_, alpha_, threshold_min_;
  std::vector<double> thresholds_;  // per cell
  // The pending batch: each child's sample (gene steps) and emitter.
  std::vector<Vector> samples_;
  std::vector<size_t> owners_;
};

}  // namespace

extern const ArchiveOptimizerKind kCmaMaeOptimizer;
const ArchiveOptimizerKind kCmaMaeOptimizer = {
    "cma-mae", "CMA-MAE",
    "CMA-MAE (Fontaine & Nikolaidis 2023): CMA-ES emitters ranked by how far their children "
    "beat a threshold per cell that anneals towards the elites",
    &kParams,
    [](const SearchScene& scene, MapElitesState state) -> std::unique_ptr<ArchiveOptimizer> {
      return std::make_unique<CmaMae>(kCmaMaeOptimizer, scene, std::move(state));
    }};

}  // namespace hexgait
