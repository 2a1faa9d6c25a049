// MAP-Elites (Mouret & Clune 2015; Cully et al. 2015) over the paper's genome: an archive with
// one cell per behaviour (ga/behaviour.h, binned), each holding the farthest-walking genome
// found with that behaviour. Children are made from elites picked uniformly at random, by the
// GA's own operators (ga/variation.h), so MAP-Elites and the paper's GA differ only in what
// they keep. A gait enters only if it stands the whole test: the archive is a repertoire of
// gaits, not of ways to fall.
//
// Children are made and evaluated a batch at a time (search/map_elites_optimizer.h: an
// optimizer of the search driver), and offered to the archive in order; every random choice is
// drawn on the calling thread from a stream per (seed, batch), so the archive does not depend on
// threads, lanes or ranks, and a run resumed from the state after any batch gives the same bits as
// one never interrupted.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "ga/behaviour.h"
#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/step_loop.h"
#include "util/param_table.h"

namespace hexgait {

// Archives written before the optimizers were registered name none: MAP-Elites filled them.
inline constexpr const char* kOriginalArchiveAlgorithm = "map-elites";

// The most cells an archive may have (bins^dimensions): about 250 bytes each in memory.
inline constexpr long long kMaxArchiveCells = 1000000;

struct MapElitesParams {
  uint64_t seed = 1;
  long long evaluations = 100000;  // the budget, every evaluation counted
  int batch = 500;                 // children made from the archive, then evaluated together
  std::string descriptor = "duty";
  int bins = 5;  // per axis, as Cully et al.
  // The optimizer that fills the archive (search/optimizers.cc) and its own parameters, by its
  // table: MAP-Elites' rates, CMA-MAE's emitters.
  std::string algorithm = kOriginalArchiveAlgorithm;
  ParamValues settings;
  bool symmetric = false;
  int threads = 0;
  int batch_lanes = 0;
  Precision precision = Precision::kDouble;
  // Float only: every child whose float result would enter the archive is run again in double,
  // and the double result is what is offered, so every elite stands in double while most
  // children (93% over 100,000: those float keeps out) cost a float evaluation only
  // (docs/speed.md, "The repertoire's precision").
  bool confirm_in_double = false;
  RunOptions run;  // stop_at_fall saves the time a fallen child would waste: it never enters
};

struct Elite {
  Genome genome;
  RunResult result;
  double fitness = 0;      // distance walked
  long long found_at = 0;  // the evaluation (1-based) that found it
};

// The archive: bins^dims cells, cell index row-major with the first axis most significant.
class Archive {
 public:
  Archive(int dims, int bins);
  int dims() const { return dims_; }
  int bins() const { return bins_; }
  long long cells() const { return static_cast<long long>(cells_.size()); }
  // The cell of a behaviour: on each axis bin min(bins - 1, floor(b * bins)).
  int CellOf(const double* behaviour) const;
  void BinsOf(int cell, int* bins) const;

  // Keeps `candidate` in `cell` if the cell is empty or it walks farther (ties keep the
  // incumbent). Returns whether it was kept.
  bool Offer(int cell, Elite&& candidate);
  const std::optional<Elite>& at(int cell) const { return cells_[static_cast<size_t>(cell)]; }
  // Filled cells in the order they were first filled (parents are drawn from this list).
  const std::vector<int>& filled() const { return filled_; }
  // Sum over elites of max(0, distance): walking farther or filling more cells raises it.
  double QdScore() const;
  // The elite that walks farthest (lowest cell on a tie); null when empty.
  const Elite* Best() const;

 private:
  int dims_, bins_;
  std::vector<std::optional<Elite>> cells_;
  std::vector<int> filled_;
};

// Where a run stands after a batch.
struct ArchiveStats {
  long long evaluations = 0;
  int filled = 0;
  double qd_score = 0;
  double best = 0;  // farthest distance in the archive (0 while empty)
  double seconds = 0;
  long long diverged = 0;  // evaluations so far whose simulation diverged (never "fell")
  // Under confirm_in_double, so far: children run again in double, and those of them that did
  // not stand in double (float admitted them, double did not).
  long long confirmed = 0;
  long long refuted = 0;
};

// Everything needed to continue a run (ga/map_elites_checkpoint.h stores it).
struct MapElitesState {
  MapElitesParams params;
  int batches = 0;  // completed
  long long evaluations = 0;
  Archive archive{1, 1};
  std::vector<ArchiveStats> history;  // one per completed batch
  // What the algorithm keeps besides the archive (CMA-MAE: its emitters and thresholds), as it
  // saves it; null for MAP-Elites.
  nlohmann::json algorithm_state;
};

// "double", "float", or "float, admissions confirmed in double".
std::string PrecisionText(const MapElitesParams& params);
// Throws InputError naming the bad parameter (with the descriptor's dimension on `model`); the
// algorithm's own settings are its optimizer's to check.
void ValidateMapElitesParams(const MapElitesParams& params, const CreatureModel& model);
EvaluatorConfig EvaluatorConfigFor(const MapElitesParams& params);
// A fresh state: the empty archive these parameters describe on `model`.
MapElitesState StartMapElites(const MapElitesParams& params, const CreatureModel& model);

// Whether a run may enter an archive: it stood the whole test and its distance is finite.
bool IsStandingGait(const RunResult& result);
// Whether OfferToArchive would keep a genome with this result (its cell is empty or it walks
// farther than the cell's elite).
bool WouldEnterArchive(const Archive& archive, const BehaviourDescriptor& descriptor,
                       const CreatureModel& model, const RunResult& result);
// Offers an evaluated genome to `archive` under `descriptor`, if it is a standing gait.
bool OfferToArchive(Archive& archive, const BehaviourDescriptor& descriptor,
                    const CreatureModel& model, Elite&& candidate);
ArchiveStats StatsOf(const Archive& archive, long long evaluations, double seconds);

// Up to `count` cells whose elites show the repertoire: the farthest walker first, then, among
// the elites walking at least the median elite's distance, each time the one whose behaviour is
// farthest (L1, to the nearest already chosen) from those chosen. In choice order.
std::vector<int> ChooseShowcase(const Archive& archive, const BehaviourDescriptor& descriptor,
                                const CreatureModel& model, int count);

}  // namespace hexgait
