// The one seam between simulation and evolution: a population of rest-length tables in, their
// RunResults out. Which kernel runs them (scalar, SIMD lanes, the creature kernel), in which
// precision, on how many threads and on how many MPI ranks is decided here, once, and is
// invisible to the optimizer (the GA today; anything that proposes rest lengths tomorrow).
// Every backend gives the same bits for the same tables: results never depend on the kernel
// choice, the batching, the thread count or the rank count (docs/model.md, "Determinism").
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/step_loop.h"
#include "util/progress.h"
#include "util/stop_signal.h"

namespace hexgait {

struct EvaluatorConfig {
  RunOptions run;
  int threads = 0;  // 0: all hardware threads
  // Creatures per batch: 0 picks (PlanBatches), 1 runs the scalar path; results do not change.
  int batch_lanes = 0;
  // Float needs the explicit Euler integrator and always runs batched (docs/model.md).
  Precision precision = Precision::kDouble;
  // On a stop request (util/stop_signal.h), the local backend abandons the batches under way
  // at their next check interval (or a scalar run at its end) and throws EvaluationStopped, so
  // a Ctrl-C is honoured within milliseconds instead of a whole population. The MPI backend
  // turns it off for its ranks' shares: rank 0 must collect every result it handed out.
  bool stop_on_request = true;
  // Runs that can end early (stop_at_fall, early_stop) refill finished lanes with the next
  // creature (sim/lane_refill.h); off only to measure what that saves (bench speed).
  bool refill_lanes = true;
};

// Thrown by Evaluate when a stop was requested before the population was whole: every result
// of that call is dropped, so the caller's state is as before the call (a search resumes by
// asking for the same population again).
class EvaluationStopped : public Stopped {
 public:
  EvaluationStopped(int done, int total);
  int done;   // results that were computed and dropped
  int total;  // the population's size
};

// The evaluator settings of a search's parameters: any struct with run, threads, batch_lanes
// and precision members (EvolutionParams, MapElitesParams).
template <class SearchParams>
EvaluatorConfig EvaluatorConfigOf(const SearchParams& params) {
  return {params.run, params.threads, params.batch_lanes, params.precision};
}

// Tables to run a second time, in double, picked by their first result: a float search's
// confirmations (search/archive_optimizer.h). A backend that can runs each as soon as its
// first result is in, beside the rest of the population, so the machine never waits for them
// at the end.
struct FollowUps {
  // Whether a first result calls for the run in double. Called once per table, from any of the
  // evaluator's threads, as soon as that result is final: it may only read.
  std::function<bool(const RunResult&)> wanted;
  // Set by EvaluateWithFollowUps, one entry per table: ran[i] = 1 when in_double[i] holds
  // table i's run in double, 0 when it was not wanted or the backend did not run it.
  std::vector<RunResult> in_double;
  std::vector<char> ran;
};

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  // results[i] belongs to tables[i]. Throws what the simulation throws (InputError, ...).
  virtual std::vector<RunResult> Evaluate(std::span<const RestLengthTable> tables,
                                          const Progress& on_progress = {}) = 0;
  // Evaluate, and the follow-ups `follow_ups.wanted` picks where this backend overlaps them
  // with the evaluation (the local one in float lanes); the caller runs the rest itself. This
  // default runs none.
  virtual std::vector<RunResult> EvaluateWithFollowUps(std::span<const RestLengthTable> tables,
                                                       FollowUps& follow_ups,
                                                       const Progress& on_progress = {}) {
    follow_ups.in_double.assign(tables.size(), RunResult{});
    follow_ups.ran.assign(tables.size(), 0);
    return Evaluate(tables, on_progress);
  }
  // One line for logs: backend, ranks, threads.
  virtual std::string Describe() const = 0;
};

// Evaluate in slices of about `slice_seconds` each, calling `between(done, total)` from the
// calling thread after every slice: for a caller that must get a say every fraction of a second
// while a long population runs (Python checks for Ctrl-C there, since its own handler cannot
// run while the work holds no GIL; a command draws progress). The first slice is one vector of
// lanes per thread; later ones are sized from the time the last took. `between` may throw to
// end the work. The results are those of one Evaluate of the whole: results never depend on how
// a population is split.
std::vector<RunResult> EvaluateInSlices(Evaluator& evaluator,
                                        std::span<const RestLengthTable> tables, int threads,
                                        double slice_seconds, const Progress& between);

// Throws InputError naming the flag (--threads, --batch-lanes, --precision) a setting came from
// when it is out of range, or float lanes are asked of another integrator than explicit Euler.
void CheckEvaluatorConfig(const EvaluatorConfig& config);

// This process's threads and batched kernels. `model` and `program` must outlive it.
std::unique_ptr<Evaluator> MakeLocalEvaluator(const CreatureModel& model,
                                              const MotorProgram& program,
                                              const EvaluatorConfig& config);

// The backend for this process: across MPI ranks when the program runs under mpirun with more
// than one rank (eval/mpi_evaluator.h), else MakeLocalEvaluator. The one place backends are
// registered.
std::unique_ptr<Evaluator> MakeEvaluator(const CreatureModel& model, const MotorProgram& program,
                                         const EvaluatorConfig& config);

// How many creatures each batch gets: `pending` split into batches of at most `batch_lanes`
// (0: at least the CPU's vector width in `precision`, enough to keep `threads` threads busy, at
// most PreferredBatchLanes), as evenly as possible. With `creature_kernel` (float batches of up to
// kCreatureKernelMaxBatch run on it, sim/creature_simulation.h) and batch_lanes 0, a count
// that gives each thread at most that many is spread over the threads instead: a creature fills
// the vectors there on its own. Sizes sum to `pending`.
std::vector<int> PlanBatches(int pending, int threads, int batch_lanes,
                             Precision precision = Precision::kDouble,
                             bool creature_kernel = false);

// `requested`, or for 0 the CPUs this process may run on (its affinity mask).
int ResolveThreadCount(int requested);

}  // namespace hexgait
