// Optimizers that fill a repertoire archive (ga/map_elites.h): MAP-Elites, CMA-MAE. What they
// share is written here once: a batch of discrete genomes per ask, admissions confirmed in
// double on tell where asked, every child offered to the archive in order, the history, and
// the archive file they save (ga/map_elites_checkpoint.h). An algorithm supplies only how it
// makes children and what it learns from their results, plus a table of its own parameters.
//
// Every random choice of batch b is drawn from the stream (seed, b) when it is asked for, so the
// archive does not depend on threads, lanes or ranks, and a run resumed from the state after any
// batch gives the same bits as one never interrupted.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "ga/map_elites.h"
#include "ga/rng.h"
#include "search/optimizer.h"
#include "util/clock.h"
#include "util/param_table.h"
#include "util/progress.h"

namespace hexgait {

class CandidateDecoder;
struct ArchiveOptimizerKind;
struct OptimizerKind;

class ArchiveOptimizer : public Optimizer {
 public:
  // Continues `state` (from StartMapElites or an archive file) with `kind`'s settings, checked.
  ArchiveOptimizer(const ArchiveOptimizerKind& kind, const SearchScene& scene,
                   MapElitesState state);
  ~ArchiveOptimizer() override;

  const Candidates& Ask() override;
  void Tell(const std::vector<RunResult>& results) override;
  bool Done() const override { return state_.evaluations >= state_.params.evaluations; }
  long long evaluations() const override { return state_.evaluations; }
  long long budget() const override { return state_.params.evaluations; }
  std::string Position() const override;
  std::string Save() const override;
  const std::shared_ptr<const GenomeLayout>& layout() const override { return layout_; }

  // The evaluator that runs the children again in double, for params.confirm_in_double
  // (MakeDoubleEvaluator); Tell throws without one. It must outlive the optimizer. When it
  // throws EvaluationStopped, the batch is not told.
  void ConfirmWith(Evaluator& in_double);
  // Under confirm_in_double with an evaluator to confirm: the children float would let in, so
  // an evaluator can run them in double beside the batch.
  FollowUps* follow_ups() override;

  const MapElitesState& state() const { return state_; }
  const ArchiveOptimizerKind& kind() const { return kind_; }
  // The children of the pending batch (after Ask, before Tell).
  size_t pending() const { return children_.size(); }

 protected:
  // The next batch: `count` children, every random choice from `rng`.
  virtual std::vector<Genome> MakeChildren(int count, Rng& rng) = 0;
  // What the algorithm learns from the batch before it is offered to the archive: each child's
  // result as offered (in double where confirmed). MAP-Elites learns nothing.
  virtual void Learn(const std::vector<RunResult>& /*results*/) {}
  // Its own state beside the archive, as the archive file's "algorithm_state": taken into
  // state() after each tell.
  virtual nlohmann::json AlgorithmState() const { return nullptr; }

  // What the genome-breeding optimizers share (their tables hold kInitialMutationRateParam):
  // `count` children, each the bits `breed` makes from the archive's elites. While nothing
  // stands yet they are the unoptimised program, then mutants of it at initial_mutation_rate,
  // as the GA starts, and `breed` is not called.
  std::vector<Genome> BreedChildren(int count, Rng& rng,
                                    const std::function<std::vector<uint8_t>(Rng&)>& breed) const;
  // An elite's genome picked uniformly at random; the archive must hold one.
  const Genome& RandomElite(Rng& rng) const;

  const CreatureModel& model_;
  const MotorProgram& program_;
  MapElitesState state_;
  std::shared_ptr<const GenomeLayout> layout_;
  const BehaviourDescriptor& descriptor_;

 private:
  const ArchiveOptimizerKind& kind_;
  std::string creature_;
  std::string damage_;  // the creature's --damage, recorded beside it
  uint64_t fingerprint_;
  double step_;

  Evaluator* in_double_ = nullptr;
  std::unique_ptr<CandidateDecoder> decoder_;  // for in_double_
  bool asked_ = false;
  FollowUps follow_ups_;  // the pending batch's
  std::vector<Genome> children_;
  Candidates candidates_;
  Clock::time_point start_;
};

struct ArchiveOptimizerKind {
  const char* name;     // the --algorithm value
  const char* title;    // for tables and headers: "MAP-Elites"
  const char* summary;  // for --help
  const ParamTable* params;
  // Continues `state` (its params.settings already hold every parameter of the table); throws
  // InputError naming what is wrong with the settings or a saved algorithm_state.
  std::unique_ptr<ArchiveOptimizer> (*make)(const SearchScene& scene, MapElitesState state);
};

// The registered kinds (search/optimizers.cc), MAP-Elites first.
const std::vector<const ArchiveOptimizerKind*>& ArchiveOptimizerKinds();
// The kind called `name`; throws InputError listing the names.
const ArchiveOptimizerKind& FindArchiveOptimizerKind(const std::string& name);

// The archive kind called `name`, or null (an `evolve` kind, or none).
const ArchiveOptimizerKind* ArchiveOptimizerKindOrNull(const std::string& name);
// The `evolve` kind called `name`; throws InputError listing the optimizers of both registries
// (for Python's Search, which takes any).
const OptimizerKind& FindOptimizerKindOfAny(const std::string& name);

// A fresh archive search: `params.algorithm`'s kind with its table's defaults in place of the
// settings not given. Throws InputError naming a bad parameter.
MapElitesState StartArchiveSearch(MapElitesParams params, const CreatureModel& model);
// The optimizer of `state`'s algorithm, continuing it.
std::unique_ptr<ArchiveOptimizer> MakeArchiveOptimizer(const SearchScene& scene,
                                                       MapElitesState state);

struct ArchiveCallbacks {
  Progress on_progress;  // the run's evaluations of its budget
  // After every batch; may throw (to stop after a Ctrl-C), ending the run with the state
  // already handed out.
  std::function<void(const MapElitesState&)> on_batch;
};

// A local evaluator of `params`'s run, threads and lanes in double: what confirms admissions.
std::unique_ptr<Evaluator> MakeDoubleEvaluator(const CreatureModel& model,
                                               const MotorProgram& program,
                                               const MapElitesParams& params);

// Runs batches until params.evaluations, continuing `state` (from StartArchiveSearch or an
// archive file) in place. `in_double` confirms admissions (params.confirm_in_double).
void RunArchiveSearch(const CreatureModel& model, const MotorProgram& program, Evaluator& evaluator,
                      MapElitesState& state, const ArchiveCallbacks& callbacks = {},
                      Evaluator* in_double = nullptr);

}  // namespace hexgait
