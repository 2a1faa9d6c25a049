// The state of a population of creatures advanced in lock-step: SimState's quantities, with
// each element widened to `lanes` consecutive values, one per creature.
// Sized once; 64-byte aligned so a lane group never straddles a cache line.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

#include "model/creature.h"
#include "sim/batch_kernel_args.h"
#include "sim/state.h"

namespace hexgait {

template <class T>
struct CacheAlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};
  CacheAlignedAllocator() = default;
  template <class U>
  CacheAlignedAllocator(const CacheAlignedAllocator<U>&) {}
  T* allocate(size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, size_t) { ::operator delete(p, kAlignment); }
  bool operator==(const CacheAlignedAllocator&) const { return true; }
};

using LaneArray = std::vector<double, CacheAlignedAllocator<double>>;

struct BatchState {
  int lanes = 0;
  // Particle i: x, y, z, vx, vy, vz, each `lanes` wide: [(i * 6 + component) * lanes + lane].
  LaneArray state;
  LaneArray rest_length;  // [spring * lanes + lane]
  LaneArray force;        // scratch: fx, fy, fz per particle, like `state`
  long long step = 0;
  double time = 0;

  double& at(int particle, int component, int lane) {
    return state[(static_cast<size_t>(particle) * 6 + component) * lanes + lane];
  }
  double at(int particle, int component, int lane) const {
    return state[(static_cast<size_t>(particle) * 6 + component) * lanes + lane];
  }
};

// Every lane holds `state` (positions, velocities, rest lengths; step and time too).
BatchState MakeBatchState(const CreatureModel& model, const SimState& state, int lanes);
// Copies lane `lane` into `out`'s positions, velocities, rest lengths, step and time; `out`
// must be sized for the model (MakeRestState). Does not allocate.
void ExtractLane(const BatchState& batch, int lane, SimState& out);
// Writes `state` into lane `lane`.
void InsertLane(const SimState& state, int lane, BatchState& batch);

// The kernel's arguments for this model and state (pointers into both).
BatchKernelArgs MakeBatchKernelArgs(const CreatureModel& model, BatchState& state, double dt);

}  // namespace hexgait
