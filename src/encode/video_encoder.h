// H.264 (libx264) in MP4 through libavcodec/libavformat, with the index at the front
// (faststart) so the file plays in browsers. Frames arrive one at a time as RGBA images and are
// converted to yuv420p (BT.709) with libswscale; memory stays flat whatever the length. The
// file is written under a temporary name and renamed into place by Finish(), so an
// interrupted encode never leaves a half-written movie.
#pragma once

#include <memory>
#include <string>

#include "image/image.h"

namespace hexgait {

class VideoEncoder {
 public:
  // Throws InputError (bad size, unwritable folder, codec missing).
  VideoEncoder(const std::string& path, int width, int height, int fps);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void Add(const Image& frame);  // frame size must match
  void Finish();                 // flushes, writes the trailer, renames into place
  long long frames() const;
  // Wall time spent so far converting RGBA to yuv420p, and in the H.264 encoder and muxer.
  double seconds_convert() const;
  double seconds_encode() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hexgait
