// MAP-Elites (Mouret & Clune 2015; Cully et al. 2015) as an archive optimizer: children are
// made from elites picked uniformly at random, by the GA's own operators (ga/variation.h), so
// MAP-Elites and the paper's GA differ only in what they keep. While nothing stands yet, the
// children are mutants of the paper's unoptimised program, as the GA starts.
#include "search/archive_optimizer.h"

#include "ga/evolution.h"
#include "ga/variation.h"

namespace hexgait {
namespace {

const ParamTable kParams = {
    {"crossover_rate", false, 0.7, 0, 1,
     "Probability a child is a one-point crossover of two elites (the GA's)"},
    {"mutation_rate", false, 0.01, 0, 1, "Per-bit mutation probability (the GA's)"},
    kInitialMutationRateParam,
};

class MapElites final : public ArchiveOptimizer {
 public:
  using ArchiveOptimizer::ArchiveOptimizer;

 private:
  std::vector<Genome> MakeChildren(int count, Rng& rng) override {
    const ParamValues& settings = state_.params.settings;
    const double crossover_rate = settings.Get("crossover_rate");
    const double mutation_rate = settings.Get("mutation_rate");
    return BreedChildren(count, rng, [&](Rng& r) {
      std::vector<uint8_t> bits = RandomElite(r).ToBits();
      if (r.Bernoulli(crossover_rate)) CrossOver(bits, RandomElite(r).ToBits(), r);
      MutateBits(bits, mutation_rate, r);
      return bits;
    });
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
