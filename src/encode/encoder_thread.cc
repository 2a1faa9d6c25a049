#include "encode/encoder_thread.h"

#include <algorithm>
#include <chrono>

#include "util/clock.h"
#include "util/error.h"

namespace hexgait {

EncoderThread::EncoderThread(VideoEncoder& encoder, int queued_frames)
    : encoder_(encoder), slots_(static_cast<size_t>(std::max(1, queued_frames))) {
  for (int i = 0; i < static_cast<int>(slots_.size()); ++i) free_.push_back(i);
  worker_ = std::thread([this] { Work(); });
}

EncoderThread::~EncoderThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    ready_.clear();  // abandoned: the movie is not finished
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void EncoderThread::RethrowWorkerError() {
  if (error_) std::rethrow_exception(error_);
}

void EncoderThread::Add(const Image& frame) {
  if (frame.width != encoder_.width() || frame.height != encoder_.height()) {
    throw SystemError("frame size does not match the movie");
  }
  int slot = -1;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !free_.empty() || error_; });
    RethrowWorkerError();
    slot = free_.front();
    free_.pop_front();
  }
  // Converted outside the lock: the worker only touches slots in `ready_`.
  const auto start = Clock::now();
  RgbaToYuv420(frame, &slots_[static_cast<size_t>(slot)]);
  seconds_convert_ += SecondsSince(start);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ready_.push_back(slot);
  }
  changed_.notify_all();
}

void EncoderThread::Finish() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return free_.size() == slots_.size() || error_; });
    RethrowWorkerError();
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
  RethrowWorkerError();
  encoder_.Finish();
}

void EncoderThread::Work() {
  while (true) {
    int slot = -1;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return !ready_.empty() || stopping_; });
      if (ready_.empty()) return;  // stopping with nothing left
      slot = ready_.front();
      ready_.pop_front();
    }
    try {
      const Yuv420Frame& frame = slots_[static_cast<size_t>(slot)];
      const uint8_t* const planes[3] = {frame.plane(0), frame.plane(1), frame.plane(2)};
      const int strides[3] = {frame.stride(0), frame.stride(1), frame.stride(2)};
      encoder_.AddYuv(planes, strides);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::current_exception();
      changed_.notify_all();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      free_.push_back(slot);
    }
    changed_.notify_all();
  }
}

}  // namespace hexgait
