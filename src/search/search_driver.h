// The loop every search runs, written once: ask, decode, evaluate through the Evaluator, tell,
// then the hooks: a line of progress, a checkpoint at the cadence asked for, and a stop after a
// Ctrl-C or SIGTERM once the state is saved. Commands and Python supply only the hooks.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "search/optimizer.h"

namespace hexgait {

// Candidates into rest-length tables: the geometric table is computed once per search.
class CandidateDecoder {
 public:
  CandidateDecoder(const CreatureModel& model, const MotorProgram& program,
                   std::shared_ptr<const GenomeLayout> layout);
  std::vector<RestLengthTable> Decode(const Candidates& candidates) const;
  const GenomeLayout& layout() const { return *layout_; }

 private:
  const CreatureModel& model_;
  std::shared_ptr<const GenomeLayout> layout_;
  RestLengthTable geometric_;
};

struct SearchHooks {
  Progress on_progress;              // the run's evaluations of its budget, from the calling thread
  std::function<void()> after_tell;  // after each Tell (a line of output, a history entry)
  // Writes optimizer.Save() somewhere; called after a Tell once `save_every_seconds` have passed
  // since the last save (0: after every Tell), when the search is done, and when a stop was
  // requested. May be empty (nothing saved).
  std::function<void(const std::string& state)> save;
  double save_every_seconds = 0;
  // Appended to the Stopped message: how to continue ("; continue it with: ...").
  std::string resume_hint;
};

// Runs `optimizer` until Done. After a save, a requested stop (util/stop_signal.h) throws
// Stopped naming optimizer.Position() and the hint, at the end of the population or, when the
// evaluator drops it half-way (EvaluationStopped), with the state after the last Tell saved
// instead; either way the saved state continues the run with the same bits as one never
// interrupted.
void RunSearch(Optimizer& optimizer, Evaluator& evaluator, const CandidateDecoder& decoder,
               const SearchHooks& hooks = {});

// What a batch of results answers: the scene, the run, the precision and every rest-length
// table evaluated, in order. Python's Search.tell refuses results whose fingerprint is not its
// last ask's (results of other candidates, or of an evaluator of another creature or run).
uint64_t EvaluationFingerprint(const CreatureModel& model, const MotorProgram& program,
                               const RunOptions& run, Precision precision,
                               const std::vector<RestLengthTable>& tables);

// One step of it, for callers that drive the loop themselves (Python): ask, evaluate, tell.
void SearchStep(Optimizer& optimizer, Evaluator& evaluator, const CandidateDecoder& decoder,
                const Progress& on_progress = {});

}  // namespace hexgait
