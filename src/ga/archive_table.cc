#include "ga/archive_table.h"

#include <algorithm>

namespace hexgait {

std::vector<ArchiveColumn> ArchiveTable(const CreatureModel& model,
                                        const BehaviourDescriptor& descriptor,
                                        const Archive& archive, double gene_length_step) {
  std::vector<int> cells = archive.filled();
  std::sort(cells.begin(), cells.end());
  const std::vector<std::string> axes = descriptor.axes(model);
  size_t genes = 0;
  bool continuous = false;  // CMA-ES and CMA-MAE elites: offsets in length units, not genes
  for (int cell : cells) {
    genes = archive.at(cell)->genome.genes().size();
    continuous = continuous || archive.at(cell)->genome.continuous();
  }
  std::vector<ArchiveColumn> table;
  const auto add = [&](const std::string& name, bool integer) -> ArchiveColumn& {
    table.push_back({name, integer, {}, {}});
    return table.back();
  };
  add("index", true);
  add("objective", false);
  for (size_t a = 0; a < axes.size(); ++a) add("measures_" + std::to_string(a), false);
  for (size_t g = 0; g < genes; ++g) add("solution_" + std::to_string(g), !continuous);
  for (const std::string& a : axes) add("bin_" + a, true);
  add("found_at", true);
  add("mean_feet_on_ground", false);

  std::vector<int> bins(axes.size());
  for (int cell : cells) {
    const Elite& e = *archive.at(cell);
    archive.BinsOf(cell, bins.data());
    const std::vector<double> measures = BehaviourOf(model, descriptor, e.result);
    size_t c = 0;
    table[c++].ints.push_back(cell);
    table[c++].reals.push_back(e.fitness);
    for (double m : measures) table[c++].reals.push_back(m);
    for (size_t g = 0; g < genes; ++g, ++c) {
      if (continuous) {
        table[c].reals.push_back(e.genome.Offset(static_cast<int>(g), gene_length_step));
      } else {
        table[c].ints.push_back(e.genome.gene(static_cast<int>(g)));
      }
    }
    for (int b : bins) table[c++].ints.push_back(b);
    table[c++].ints.push_back(e.found_at);
    table[c++].reals.push_back(e.result.mean_feet_on_ground);
  }
  return table;
}

}  // namespace hexgait
