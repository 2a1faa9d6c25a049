// Reads a movie back frame by frame as RGBA images, through the same on-demand FFmpeg
// libraries the encoder uses: what `hexgait compare` and `--expect` check a movie with. Only
// yuv420p video (what hexgait writes, and what nearly every H.264 file is) is converted; the
// conversion is the exact inverse of the encoder's (BT.709, limited range), chroma shared by each
// 2x2 block.
#pragma once

#include <memory>
#include <string>

#include "image/image.h"

namespace hexgait {

class VideoReader {
 public:
  // Opens `path` and its best video stream. Throws InputError naming the file when it is not a
  // movie FFmpeg can decode, SystemError when FFmpeg cannot be loaded.
  explicit VideoReader(const std::string& path);
  ~VideoReader();
  VideoReader(const VideoReader&) = delete;
  VideoReader& operator=(const VideoReader&) = delete;

  int width() const;
  int height() const;
  // The next frame into `frame` (resized to match); false after the last one. Throws InputError
  // naming the file for a corrupt stream or a pixel format other than yuv420p.
  bool Next(Image* frame);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hexgait
