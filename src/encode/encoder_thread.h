// Runs a VideoEncoder on a thread of its own, so colour conversion and H.264 encoding of one
// frame overlap the rendering of the next (on two cores this is what makes the in-process
// pipeline faster than piping frames into a separate ffmpeg process). A fixed ring of frame
// buffers bounds the memory; Add blocks while all of them wait to be encoded.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "encode/video_encoder.h"

namespace hexgait {

class EncoderThread {
 public:
  EncoderThread(VideoEncoder& encoder, int queued_frames = 3);
  // Stops the worker; a movie not finished is left unwritten (VideoEncoder removes its file).
  ~EncoderThread();
  EncoderThread(const EncoderThread&) = delete;
  EncoderThread& operator=(const EncoderThread&) = delete;

  // Copies the frame into a free buffer and queues it. Rethrows an error of the worker.
  void Add(const Image& frame);
  // Encodes what is queued, then finishes the movie (VideoEncoder::Finish) on this thread.
  void Finish();

 private:
  void Work();
  void RethrowWorkerError();

  VideoEncoder& encoder_;
  std::vector<Image> slots_;
  std::deque<int> free_, ready_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::thread worker_;
};

}  // namespace hexgait
