// A fixed-capacity FIFO: pushing into a full ring drops the oldest item. The gait cues keep
// their history in these, so a movie's memory stays flat however long it runs.
#pragma once

#include <cassert>
#include <cstddef>
#include <vector>

namespace hexgait {

template <typename T>
class RingBuffer {
 public:
  explicit RingBuffer(size_t capacity) : items_(capacity) { assert(capacity > 0); }

  void Push(const T& item) {
    ++pushed_;
    items_[(first_ + size_) % items_.size()] = item;
    if (size_ < items_.size()) {
      ++size_;
    } else {
      first_ = (first_ + 1) % items_.size();
    }
  }
  void Clear() { first_ = size_ = 0; }
  // Items pushed since construction, dropped ones included: a reader that keeps every item (a
  // replay's footprints) takes the newest pushed() - last_seen after each round of pushes.
  size_t pushed() const { return pushed_; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  size_t capacity() const { return items_.size(); }
  // 0 is the oldest item, size() - 1 the newest.
  const T& operator[](size_t i) const { return items_[(first_ + i) % items_.size()]; }
  const T& back() const { return (*this)[size_ - 1]; }

 private:
  std::vector<T> items_;
  size_t first_ = 0, size_ = 0, pushed_ = 0;
};

}  // namespace hexgait
