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

namespace hexgait {

class MapElitesOptimizer final : public Optimizer {
 public:
  // Continues `state` (from StartMapElites or a checkpoint); `creature` is recorded in Save().
  MapElitesOptimizer(const CreatureModel& model, const MotorProgram& program, MapElitesState state,
                     const std::string& creature = "");

  const Candidates& Ask() override;
  void Tell(const std::vector<RunResult>& results) override;
  bool Done() const override { return state_.evaluations >= state_.params.evaluations; }
  long long evaluations() const override { return state_.evaluations; }
  long long budget() const override { return state_.params.evaluations; }
  std::string Position() const override;
  std::string Save() const override;
  const std::shared_ptr<const GenomeLayout>& layout() const override { return layout_; }

  // Runs candidates in double (the driver's decoder and a double evaluator), for
  // params.confirm_in_double; Tell throws without one. It may throw EvaluationStopped: the
  // batch is then not told.
  using Confirmer = std::function<std::vector<RunResult>(const Candidates&)>;
  void SetConfirmer(Confirmer confirm) { confirm_ = std::move(confirm); }

  const MapElitesState& state() const { return state_; }
  // The children of the pending batch (after Ask, before Tell).
  size_t pending() const { return children_.size(); }

 private:
  const CreatureModel& model_;
  MapElitesState state_;
  std::string creature_;
  uint64_t fingerprint_;
  std::shared_ptr<const GenomeLayout> layout_;
  const BehaviourDescriptor& descriptor_;
  double step_;

  Confirmer confirm_;
  bool asked_ = false;
  std::vector<Genome> children_;
  Candidates candidates_;
  std::chrono::steady_clock::time_point start_;
};

struct MapElitesCallbacks {
  std::function<void(int done, int total)> on_progress;  // within a batch, calling thread
  // After every batch; may throw (to stop after a Ctrl-C), ending the run with the state
  // already handed out.
  std::function<void(const MapElitesState&)> on_batch;
};

// Runs batches until params.evaluations, continuing `state` (from StartMapElites or a
// checkpoint) in place. `in_double` confirms admissions (params.confirm_in_double).
void RunMapElites(const CreatureModel& model, const MotorProgram& program, Evaluator& evaluator,
                  MapElitesState& state, const MapElitesCallbacks& callbacks = {},
                  Evaluator* in_double = nullptr);

}  // namespace hexgait
