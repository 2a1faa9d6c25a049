// MAP-Elites (ga/map_elites.h) as an optimizer of the search driver: one batch of children per
// ask, offered to the archive in order on tell.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "eval/evaluator.h"
#include "ga/map_elites.h"
#include "search/optimizer.h"
#include "util/clock.h"

namespace hexgait {

class CandidateDecoder;

class MapElitesOptimizer final : public Optimizer {
 public:
  // Continues `state` (from StartMapElites or a checkpoint); `creature` is recorded in Save().
  MapElitesOptimizer(const CreatureModel& model, const MotorProgram& program, MapElitesState state,
                     const std::string& creature = "");
  ~MapElitesOptimizer() override;

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

  const MapElitesState& state() const { return state_; }
  // The children of the pending batch (after Ask, before Tell).
  size_t pending() const { return children_.size(); }

 private:
  const CreatureModel& model_;
  const MotorProgram& program_;
  MapElitesState state_;
  std::string creature_;
  std::string damage_;  // the creature's --damage, recorded beside it
  uint64_t fingerprint_;
  std::shared_ptr<const GenomeLayout> layout_;
  const BehaviourDescriptor& descriptor_;
  double step_;

  Evaluator* in_double_ = nullptr;
  std::unique_ptr<CandidateDecoder> decoder_;  // for in_double_
  bool asked_ = false;
  std::vector<Genome> children_;
  Candidates candidates_;
  Clock::time_point start_;
};

struct MapElitesCallbacks {
  std::function<void(int done, int total)> on_progress;  // within a batch, calling thread
  // After every batch; may throw (to stop after a Ctrl-C), ending the run with the state
  // already handed out.
  std::function<void(const MapElitesState&)> on_batch;
};

// A local evaluator of `params`'s run, threads and lanes in double: what confirms admissions.
std::unique_ptr<Evaluator> MakeDoubleEvaluator(const CreatureModel& model,
                                               const MotorProgram& program,
                                               const MapElitesParams& params);

// Runs batches until params.evaluations, continuing `state` (from StartMapElites or a
// checkpoint) in place. `in_double` confirms admissions (params.confirm_in_double).
void RunMapElites(const CreatureModel& model, const MotorProgram& program, Evaluator& evaluator,
                  MapElitesState& state, const MapElitesCallbacks& callbacks = {},
                  Evaluator* in_double = nullptr);

}  // namespace hexgait
