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
  // The index into the tables of the next creature to run, -1 when none is left, or kLater
  // when none is ready yet but one may come (a follow-up stream: EvaluateRefilledWithFollowUps).
  // Called from the running thread only; streams on several threads may share one counter.
  static constexpr int kLater = -2;
  std::function<int()> claim;
  // After results[index] is final (for progress).
  std::function<void(int index)> finished = {};
  // Polled between chunks of at most one check interval: true abandons the runs under way.
  std::function<bool()> stop = {};
  // A follow-up stream only: blocks until claim may have something (called when the thread
  // has nothing else to run).
  std::function<void()> wait = {};
};

// How full refilled lanes were kept: lane-steps the kernels stepped, and of those the ones in
// which the lane ran a creature. The rest stepped an empty lane: one waiting for the last
// creatures of its stream to finish, or for follow-ups to come.
struct LaneSteps {
  long long stepped = 0;
  long long running = 0;
};

// The lane-steps of every refilled run this process has finished in `precision`, from its
// start; a caller measures its own work as the difference of two readings. Each run adds its
// counts once, at its end (thread-safe).
LaneSteps RefilledLaneSteps(Precision precision);

// Runs tables[i] for every i the stream hands out, in `lanes` lanes (a compiled count) of
// `precision`, writing results[i]. The run must be one the batched paths accept
// (BatchedPathAccepts). Returns false when `stop` ended it (the results of the runs under way
// are then not written).
bool EvaluateRefilled(const CreatureModel& model, const MotorProgram& program,
                      std::span<const RestLengthTable> tables, const RunOptions& options, int lanes,
                      std::span<RunResult> results, const RefillStream& stream,
                      BatchIsa isa = BatchIsa::kAuto, Precision precision = Precision::kDouble);

// The same, with a second run on the same thread taking turns with the first, chunk by chunk:
// `follow_ups` hands out tables (of the same `tables`) to run again in double, in
// `follow_up_lanes` double lanes, into follow_up_results[i], typically tables whose first run
// just finished (its `finished` pushes them). The first run is in `precision`. Each result is
// still the one its run alone gives: lanes never interact. `stream.stop` is polled for both;
// `follow_ups.wait` is required. Returns false when a stop ended it.
bool EvaluateRefilledWithFollowUps(const CreatureModel& model, const MotorProgram& program,
                                   std::span<const RestLengthTable> tables,
                                   const RunOptions& options, int lanes,
                                   std::span<RunResult> results, const RefillStream& stream,
                                   int follow_up_lanes, std::span<RunResult> follow_up_results,
                                   const RefillStream& follow_ups, Precision precision);

}  // namespace hexgait
