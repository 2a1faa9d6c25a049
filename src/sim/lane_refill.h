// Batched evaluations in which a finished creature makes room: each lane runs its own creature
// on its own clock (motor/lane_clocked_controller.h), and the moment a run ends (a fall under
// stop_at_fall, a divergence, rest under early_stop, or the end of its time) the lane takes the
// next table at once instead of being stepped, unused, until the batch's last lane is done.
// Every result is bit-identical to EvaluateRestLengths's for the same table (EvaluateBatched's
// in float), whatever the lane count, the order tables are handed out in, the instruction set
// and the thread count: a lane performs the scalar path's operations in its order, and is
// checked by the same RunMonitor at its own steps.
#pragma once

#include <functional>
#include <span>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "sim/batch_kernel.h"
#include "sim/step_loop.h"

namespace hexgait {

struct RefillStream {
  // The index into the tables of the next creature to run, or -1 when none is left. Called
  // from the running thread only; streams on several threads may share one atomic counter.
  std::function<int()> claim;
  // After results[index] is final (for progress).
  std::function<void(int index)> finished = {};
  // Polled between chunks of at most one check interval: true abandons the runs under way.
  std::function<bool()> stop = {};
};

// Runs tables[i] for every i the stream hands out, in `lanes` lanes (a compiled count) of
// `precision`, writing results[i]. The run must be one the batched paths accept
// (BatchedPathAccepts). Returns false when `stop` ended it (the results of the runs under way
// are then not written).
bool EvaluateRefilled(const CreatureModel& model, const MotorProgram& program,
                      std::span<const RestLengthTable> tables, const RunOptions& options, int lanes,
                      std::span<RunResult> results, const RefillStream& stream,
                      BatchIsa isa = BatchIsa::kAuto, Precision precision = Precision::kDouble);

}  // namespace hexgait
