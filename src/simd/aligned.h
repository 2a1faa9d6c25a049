// 64-byte-aligned vectors: whole-vector loads of lane groups never straddle a cache line. Shared
// by the batched simulator (sim/batch_state.h) and the batch motor controller, so it lives
// below both.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

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

template <class T>
using LaneArrayT = std::vector<T, CacheAlignedAllocator<T>>;

}  // namespace hexgait
