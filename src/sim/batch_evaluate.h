// Fitness evaluations of several rest-length tables at once: the creatures run in lock-step in the
// lanes of the batched kernel (sim/batch_kernel.h). In double, each result is bit-identical to
// EvaluateRestLengths's for the same table: same forces, same controller values, the same fall and
// divergence checks at the same steps, per lane. In float, the same sequence of operations runs
// in single precision (docs/model.md, "Float lanes"). A lane whose run ends early (divergence,
// early stop) keeps being stepped but its result is frozen at the step where the scalar run
// would have stopped.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "model/creature.h"
#include "motor/batch_controller.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/batch_state.h"
#include "sim/creature_simulation.h"
#include "sim/lane_measures.h"
#include "sim/step_loop.h"

namespace hexgait {

// Creatures with one rest-length table each, advanced in lock-step with explicit Euler in lanes
// of T (double or float). `lanes` 0 picks the narrowest kernel that holds them all; unused lanes
// run copies of the first table.
template <class T>
class BatchSimulation {
 public:
  BatchSimulation(const CreatureModel& model, const MotorProgram& program,
                  std::span<const RestLengthTable> tables, double dt, int lanes = 0,
                  BatchIsa isa = BatchIsa::kAuto);
  BatchSimulation(const BatchSimulation&) = delete;
  BatchSimulation& operator=(const BatchSimulation&) = delete;

  // `steps` explicit Euler steps of every lane. Does not allocate.
  void Advance(long long steps) {
    for (long long k = 0; k < steps; ++k) {
      controller_.Update(state_.step, state_.rest_length.data());
      step_fn_(args_);
      ++state_.step;
    }
    state_.time = static_cast<double>(state_.step) * dt_;
  }
  // Lane `lane`'s state, widened to double; `out` must be sized for the model.
  void Extract(int lane, SimState& out) const { ExtractLane(state_, lane, out); }
  // Every lane's fall-check measures at once (sim/lane_measures.h); spans of lanes() values.
  void Measure(const CreatureModel& model, double limit, std::span<BodyMeasures> body,
               std::span<char> in_bounds) const {
    MeasureLanes(model, state_, limit, 0, state_.lanes, body, in_bounds, isa_);
  }

  int lanes() const { return state_.lanes; }
  long long step() const { return state_.step; }
  double time() const { return state_.time; }
  double cycle_period() const { return controller_.cycle_period(); }

 private:
  double dt_;
  BatchIsa isa_;
  BatchMotorController controller_;
  BatchStateT<T> state_;
  BatchKernelArgsT<T> args_;
  BatchStepFnT<T> step_fn_;
};

// Float batches up to this size run on the creature kernel when it is available (and `lanes`
// is 0): measured by `hexgait bench speed`, it is faster per creature than lanes up to here.
inline constexpr int kCreatureKernelMaxBatch = 4;

// The one rule of which runs the batched paths (lanes and the creature kernel) accept: the
// paper's scene, explicit Euler on flat ground without a push. nullptr when they accept it,
// else the reason ("runs the explicit Euler integrator only"). Every caller that chooses a path
// asks this, so a new condition is one edit.
const char* BatchedPathRefusal(const CreatureModel& model, const RunOptions& options);
inline bool BatchedPathAccepts(const CreatureModel& model, const RunOptions& options) {
  return BatchedPathRefusal(model, options) == nullptr;
}
// Whether EvaluateBatched runs a batch of `count` (with these `lanes`, `isa` and `precision`) on
// the creature kernel instead of lanes.
bool RunsOnCreatureKernel(const CreatureModel& model, int count, int lanes, BatchIsa isa,
                          Precision precision);

// Evaluates `tables` (at most kMaxBatchLanes) on the calling thread with the explicit Euler
// integrator (options.integrator must be kEuler), in lanes of `precision`. `lanes` 0 picks the
// narrowest kernel that holds them all, or for float and at most kCreatureKernelMaxBatch
// tables the creature kernel where CreatureSimulation::Available (the same bits either way);
// unused lanes run copies of the first table and are ignored. `stop`, when given, is polled
// every check interval (a few microseconds of work): true abandons the batch, and the result is
// then empty (a batch of 16 double lanes of the paper's run is about a second of work on a slow
// core, too long to wait for after Ctrl-C).
std::vector<RunResult> EvaluateBatched(const CreatureModel& model, const MotorProgram& program,
                                       std::span<const RestLengthTable> tables,
                                       const RunOptions& options, int lanes = 0,
                                       BatchIsa isa = BatchIsa::kAuto,
                                       Precision precision = Precision::kDouble,
                                       const std::function<bool()>& stop = {});

// The same evaluations in float on the creature kernel (requires CreatureSimulation::Available):
// bit-identical to EvaluateBatched in float lanes.
std::vector<RunResult> EvaluateWithCreatureKernel(const CreatureModel& model,
                                                  const MotorProgram& program,
                                                  std::span<const RestLengthTable> tables,
                                                  const RunOptions& options);

}  // namespace hexgait
