// The state of a population of creatures advanced in lock-step: SimState's quantities, with
// each element widened to `lanes` consecutive values, one per creature.
// Sized once; 64-byte aligned so a lane group never straddles a cache line.
#pragma once

#include <vector>

#include "model/creature.h"
#include "sim/batch_kernel_args.h"
#include "sim/state.h"
#include "simd/aligned.h"

namespace hexgait {

using LaneArray = LaneArrayT<double>;

// T: double or float (sim/batch_kernel.h, Precision).
template <class T>
struct BatchStateT {
  int lanes = 0;
  // Particle i: x, y, z, vx, vy, vz, each `lanes` wide: [(i * 6 + component) * lanes + lane].
  LaneArrayT<T> state;
  LaneArrayT<T> rest_length;   // [spring * lanes + lane]
  LaneArrayT<T> spring_force;  // scratch: fx, fy, fz per spring, each `lanes` wide
  // The model's per-spring and per-particle constants as T, shared by the lanes.
  std::vector<T> stiffness, damping, mass, inv_mass;
  // Each particle's springs in spring order (BatchKernelArgsT::incident).
  std::vector<int> incident_start, incident;
  long long step = 0;
  double time = 0;

  T& at(int particle, int component, int lane) {
    return state[(static_cast<size_t>(particle) * 6 + component) * lanes + lane];
  }
  T at(int particle, int component, int lane) const {
    return state[(static_cast<size_t>(particle) * 6 + component) * lanes + lane];
  }
};
using BatchState = BatchStateT<double>;

// Every lane holds `state` (positions, velocities, rest lengths, rounded to T; step and time
// too).
template <class T>
BatchStateT<T> MakeBatchStateT(const CreatureModel& model, const SimState& state, int lanes);
inline BatchState MakeBatchState(const CreatureModel& model, const SimState& state, int lanes) {
  return MakeBatchStateT<double>(model, state, lanes);
}
// Copies lane `lane` into `out`'s positions, velocities, rest lengths, step and time; `out`
// must be sized for the model (MakeRestState). Does not allocate.
template <class T>
void ExtractLane(const BatchStateT<T>& batch, int lane, SimState& out);
// Writes `state` into lane `lane` (rounded to T).
template <class T>
void InsertLane(const SimState& state, int lane, BatchStateT<T>& batch);

// The kernel's arguments for this model and state (pointers into both).
template <class T>
BatchKernelArgsT<T> MakeBatchKernelArgs(const CreatureModel& model, BatchStateT<T>& state,
                                        double dt);

}  // namespace hexgait
