#include "encode/encoder_thread.h"

#include <algorithm>

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
  int slot = -1;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !free_.empty() || error_; });
    RethrowWorkerError();
    slot = free_.front();
    free_.pop_front();
  }
  // Copied outside the lock: the worker only touches slots in `ready_`.
  slots_[static_cast<size_t>(slot)] = frame;
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
      encoder_.Add(slots_[static_cast<size_t>(slot)]);
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
