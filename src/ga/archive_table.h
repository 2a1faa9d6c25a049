// A repertoire's archive as a table, one row per filled cell in cell order, in the column
// layout of pyribs' ArchiveDataFrame (what quality-diversity users load into pandas):
//   index               the cell (row-major over the bins, the first axis most significant)
//   objective           the distance its elite walks
//   measures_0..k-1     the elite's behaviour descriptor, axis by axis (for `duty`, each leg's
//                       duty factor in the creature's leg order, as the bin_ columns name them)
//   solution_0..n-1     its genes, the paper's 4-bit integers in [-8, 7]; for an archive of
//                       continuous genomes (CMA-ES, CMA-MAE) each gene's rest-length offset in
//                       length units (a discrete gene's is gene * gene_length_step)
// then hexgait's own: bin_AXIS (the cell's bin on each axis, named), found_at (the evaluation
// that found it) and mean_feet_on_ground. archive.csv is this table; so is Python's
// hexgait.load_archive.
#pragma once

#include <string>
#include <vector>

#include "ga/behaviour.h"
#include "ga/map_elites.h"

namespace hexgait {

struct ArchiveColumn {
  std::string name;
  bool integer = false;
  std::vector<long long> ints;  // when integer
  std::vector<double> reals;    // otherwise
};

std::vector<ArchiveColumn> ArchiveTable(const CreatureModel& model,
                                        const BehaviourDescriptor& descriptor,
                                        const Archive& archive, double gene_length_step);

}  // namespace hexgait
