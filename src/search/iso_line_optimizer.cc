// MAP-Elites with iso+line variation (Vassiliades & Mouret 2018, "Discovering the elite
// hypervolume by leveraging interspecies correlation"): a child of two elites picked at random
// is x + sigma_iso N(0, I) + sigma_line N(0, 1) (y - x). The line term moves along the direction
// in which elites differ, which in a map of walking gaits is where other walking gaits lie; the
// iso term explores around it. It works in the genome's own integer space: each gene is rounded
// to the nearest whole step and clipped to [-8, 7], so the children are the paper's 4-bit genomes
// and everything downstream (records, confirmations, movies) is unchanged. Until a gait stands,
// the children are bit-flip mutants of the unoptimised program, as MAP-Elites' are.
#include <algorithm>
#include <cmath>

#include "ga/evolution.h"
#include "search/archive_optimizer.h"

namespace hexgait {
namespace {

const ParamTable kIsoLineParams = {
    {"sigma_iso", false, 1, 0, 8,
     "Isotropic Gaussian step, in genes (at 1, six genes in ten move, most by one step)"},
    {"sigma_line", false, 0.2, 0, 4,
     "Gaussian step along the line to the second elite, as a fraction of their difference"},
    kInitialMutationRateParam,
};

class IsoLine final : public ArchiveOptimizer {
 public:
  using ArchiveOptimizer::ArchiveOptimizer;

 private:
  std::vector<Genome> MakeChildren(int count, Rng& rng) override {
    const ParamValues& settings = state_.params.settings;
    const double sigma_iso = settings.Get("sigma_iso");
    const double sigma_line = settings.Get("sigma_line");
    return BreedChildren(count, rng, [&](Rng& r) {
      // Every gene is written below.
      std::vector<uint8_t> bits(static_cast<size_t>(layout_->num_bits()), 0);
      const Genome& x = RandomElite(r);
      const Genome& y = RandomElite(r);
      const double line = sigma_line * r.Normal();
      for (int g = 0; g < x.num_genes(); ++g) {
        const double value = x.gene(g) + sigma_iso * r.Normal() + line * (y.gene(g) - x.gene(g));
        const double clipped =
            std::clamp(std::nearbyint(value), double{kGeneMin}, double{kGeneMax});
        EncodeGene(static_cast<int>(clipped), &bits[static_cast<size_t>(g) * kGeneBits]);
      }
      return bits;
    });
  }
};

}  // namespace

extern const ArchiveOptimizerKind kIsoLineOptimizer;
const ArchiveOptimizerKind kIsoLineOptimizer = {
    "iso-line", "MAP-Elites (iso+line)",
    "children of two elites by iso+line variation in the genes, rounded and clipped",
    &kIsoLineParams,
    [](const SearchScene& scene, MapElitesState state) -> std::unique_ptr<ArchiveOptimizer> {
      return std::make_unique<IsoLine>(kIsoLineOptimizer, scene, std::move(state));
    }};

}  // namespace hexgait
