// The fall check's measures of every lane of a batch at once: the divergence test, the body's
// lowest point and up axis, and the feet on the ground, on vectors of lanes widened to double.
// RunMonitor::CheckMeasured then checks each lane without copying its state out: copying each
// lane out and measuring it alone made `bench speed`'s 16-float-lane evaluations 1.12 times
// slower (docs/speed.md). The operations are the one-creature path's (sim/body_frame.h,
// BoundsTest), so each lane's measures are its bits.
#pragma once

#include <span>

#include "model/creature.h"
#include "sim/batch_state.h"
#include "sim/step_loop.h"
#include "simd/isa.h"

namespace hexgait {

// For each of lanes first .. first + count - 1: `in_bounds[lane]` whether every particle passes
// the divergence test with `limit`, and where it does, `body[lane]` its measures. Both spans
// hold batch.lanes values. `isa` picks the code (kAvx512: AVX-512 vectors of 8 lanes, and
// SSE2's of 2 for what is left; any other set: SSE2's; kAuto: this CPU's best), not the
// results, which are the same bits.
template <class T>
void MeasureLanes(const CreatureModel& model, const BatchStateT<T>& batch, double limit, int first,
                  int count, std::span<BodyMeasures> body, std::span<char> in_bounds,
                  BatchIsa isa = BatchIsa::kAuto);

}  // namespace hexgait
