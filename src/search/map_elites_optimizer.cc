// MAP-Elites (Mouret & Clune 2015; Cully et al. 2015) as an archive optimizer: children are
// made from elites picked uniformly at random, by the GA's own operators (ga/variation.h), so
// MAP-Elites and the paper's GA differ only in what they keep. While nothing stands yet, the
// children are mutants of the paper's unoptimised program, as the GA starts.
#include "search/archive_optimizer.h"

#include "ga/variation.h"

namespace hexgait {
namespace {

const ParamTable kParams = {
    {"crossover_rate", false, 0.7, 0, 1,
     "Probability a child is a one-point crossover of two elites (the GA's)"},
    {"mutation_rate", false, 0.01, 0, 1, "Per-bit mutation probability (the GA's)"},
    {"initial_mutation_rate", false, 0.02, 0, 1,
     "Per-bit flips of the unoptimised genome while no gait stands yet"},
};

class MapElites final : public ArchiveOptimizer {
 public:
  using ArchiveOptimizer::ArchiveOptimizer;

 private:
  std::vector<Genome> MakeChildren(int count, Rng& rng) override {
    const ParamValues& settings = state_.params.settings;
    const double crossover_rate = settings.Get("crossover_rate");
    const double mutation_rate = settings.Get("mutation_rate");
    const bool nothing_stands = state_.archive.filled().empty();
    std::vector<Genome> children;
    children.reserve(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
      std::vector<uint8_t> bits;
      if (nothing_stands) {
        bits = FirstChildBits(k, rng);
      } else {
        bits = RandomElite(rng).ToBits();
        if (rng.Bernoulli(crossover_rate)) CrossOver(bits, RandomElite(rng).ToBits(), rng);
        MutateBits(bits, mutation_rate, rng);
      }
      Genome child(layout_);
      child.FromBits(bits);
      children.push_back(std::move(child));
    }
    return children;
  }
};

}  // namespace

extern const ArchiveOptimizerKind kMapElitesOptimizer;
const ArchiveOptimizerKind kMapElitesOptimizer = {
    "map-elites", "MAP-Elites",
    "children of elites picked at random, by the GA's crossover and mutation", &kParams,
    [](const SearchScene& scene, MapElitesState state) -> std::unique_ptr<ArchiveOptimizer> {
      return std::make_unique<MapElites>(kMapElitesOptimizer, scene, std::move(state));
    }};

}  // namespace hexgait
