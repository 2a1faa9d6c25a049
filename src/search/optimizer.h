// The one interface of a search over rest-length tables, after pyribs and QDax: Ask for a batch
// of candidates, evaluate them (the driver does, through an Evaluator), Tell the results, and
// save the state in between. The GA, CMA-ES, MAP-Elites and CMA-MAE implement it; the search driver
// (search/search_driver.h) runs any of them, and Python's hexgait.Search drives the same
// objects one ask and one tell at a time, so both give the same bits.
//
// A candidate is a row of rest-length offsets in length units, one per gene of the genome layout
// (ga/genome.h): gene * gene_length_step for the discrete optimizers, real values for CMA-ES.
// OffsetRestLengths decodes a row with the bits PerturbedRestLengths gives its genome.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/step_loop.h"

namespace hexgait {

struct FollowUps;

// What an optimizer searches on: the scene, and the --creature it came from (recorded in
// checkpoints so a built-in creature resumes by name).
struct SearchScene {
  const CreatureModel& model;
  const MotorProgram& program;
  std::string creature;
};

// A batch of candidates: size() rows of dims offsets, row-major.
struct Candidates {
  int dims = 0;
  std::vector<double> offsets;
  size_t size() const { return dims > 0 ? offsets.size() / static_cast<size_t>(dims) : 0; }
  const double* row(size_t i) const { return offsets.data() + i * static_cast<size_t>(dims); }
};

class Optimizer {
 public:
  virtual ~Optimizer() = default;

  // The next candidates to evaluate. Asking again before Tell gives the same batch.
  virtual const Candidates& Ask() = 0;
  // The results of the last Ask's candidates, in order. Throws InputError when their number
  // differs or Ask was not called.
  virtual void Tell(const std::vector<RunResult>& results) = 0;
  // Whether the budget is spent: Ask must not be called any more.
  virtual bool Done() const = 0;

  // Evaluations told so far and the run's budget (for progress and estimates).
  virtual long long evaluations() const = 0;
  virtual long long budget() const = 0;
  // Where the run stands, for messages: "after generation 3 of 10".
  virtual std::string Position() const = 0;
  // The state after the last Tell as the text --resume reads (a checkpoint file's content).
  virtual std::string Save() const = 0;

  // The layout of the candidates' genes.
  virtual const std::shared_ptr<const GenomeLayout>& layout() const = 0;

  // For the last Ask: the candidates to run again in double as their first results come in
  // (eval/evaluator.h, FollowUps), or null for none. Tell uses what the evaluator filled in
  // and runs the rest itself, so results never depend on whether it did.
  virtual FollowUps* follow_ups() { return nullptr; }
};

}  // namespace hexgait
