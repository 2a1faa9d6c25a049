// H.264 (libx264) in MP4 through libavcodec/libavformat, with the index at the front
// (faststart) so the file plays in browsers. Frames arrive one at a time as RGBA images and are
// converted to yuv420p (BT.709; encode/yuv_convert.h); memory stays flat whatever the length. The
// file is written under a temporary name and renamed into place by Finish(), so an
// interrupted encode never leaves a half-written movie.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"

namespace hexgait {

// libx264's rate and speed: `preset` trades encode time for file size at the same quality,
// `crf` trades quality for size (lower is better; 0 is lossless, 51 the worst).
struct EncoderSettings {
  int fps = 30;
  std::string preset = "veryfast";
  int crf = 20;
};

// x264's presets, fastest first ("ultrafast, ..., veryslow").
const std::vector<std::string>& X264Presets();

// A frame after conversion: the yuv420p planes (Y, then U and V at half size), row by row.
using YuvFrameTap = std::function<void(const uint8_t* const planes[3], const int strides[3])>;

// Loads FFmpeg and finds its libx264 encoder, or throws SystemError naming what is missing:
// what will encode a movie after long work calls it first.
void CheckEncoderAvailable();

class VideoEncoder {
 public:
  // Throws InputError (bad size, unwritable folder, unknown preset or CRF), SystemError (FFmpeg
  // or its libx264 encoder missing, a libav call failing); so do Add and Finish when a libav
  // call fails.
  VideoEncoder(const std::string& path, int width, int height, const EncoderSettings& settings);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void Add(const Image& frame);  // frame size must match
  // A frame already in yuv420p (EncoderThread converts on the caller's thread; a benchmark's
  // encode-only reference).
  void AddYuv(const uint8_t* const planes[3], const int strides[3]);
  // Called with every frame, in yuv420p, before it is encoded (benchmarks keep them).
  void set_yuv_tap(YuvFrameTap tap);
  void Finish();  // flushes, writes the trailer, renames into place
  long long frames() const;
  int width() const;
  int height() const;
  // Wall time spent so far converting RGBA to yuv420p, and in the H.264 encoder and muxer.
  double seconds_convert() const;
  double seconds_encode() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The ffmpeg command-line tool's arguments ("ffmpeg" first) that encode raw frames of
// `input_pixel_format` ("rgba"), width x height, read from stdin into `out` as VideoEncoder does
// with `settings`: its codec, preset, CRF, frame rate, x264 threads, keyframe interval, pixel
// format, colour tags and faststart. Built next to the encoder so a comparison with the tool
// (`hexgait bench movie`) cannot drift from what is measured.
std::vector<std::string> FfmpegToolArgs(const EncoderSettings& settings, int width, int height,
                                        const std::string& input_pixel_format,
                                        const std::string& out);

}  // namespace hexgait
