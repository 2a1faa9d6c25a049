// Runs a VideoEncoder on a thread of its own, so H.264 encoding of one frame overlaps the
// rendering of the next (on two cores this is what makes the in-process pipeline faster than
// piping frames into a separate ffmpeg process). The colour conversion runs in Add, on the
// caller's thread, straight into a queued yuv420p buffer: the encoder's thread is the movie's
// critical path (x264 is most of a movie's time), so it does nothing but encode, and a queued
// frame is 1.5 bytes a pixel instead of 4. A fixed ring of buffers bounds the memory; Add
// blocks while all of them wait to be encoded.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "encode/video_encoder.h"
#include "encode/yuv_convert.h"

namespace hexgait {

class EncoderThread {
 public:
  EncoderThread(VideoEncoder& encoder, int queued_frames = 3);
  // Stops the worker; a movie not finished is left unwritten (VideoEncoder removes its file).
  ~EncoderThread();
  EncoderThread(const EncoderThread&) = delete;
  EncoderThread& operator=(const EncoderThread&) = delete;

  // Converts the frame into a free buffer and queues it. Rethrows an error of the worker.
  void Add(const Image& frame);
  // Encodes what is queued, then finishes the movie (VideoEncoder::Finish) on this thread.
  void Finish();
  // Wall time Add spent converting RGBA to yuv420p (the encoding is VideoEncoder's).
  double seconds_convert() const { return seconds_convert_; }

 private:
  void Work();
  void RethrowWorkerError();

  VideoEncoder& encoder_;
  std::vector<Yuv420Frame> slots_;
  std::deque<int> free_, ready_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool stopping_ = false;
  std::exception_ptr error_;
  double seconds_convert_ = 0;
  std::thread worker_;
};

}  // namespace hexgait
