#include "encode/video_encoder.h"

#include <algorithm>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "encode/ffmpeg_api.h"
#include "encode/yuv_convert.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/output.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

struct FormatDeleter {
  void operator()(AVFormatContext* f) const {
    if (f->pb) Ffmpeg().avio_closep(&f->pb);
    Ffmpeg().avformat_free_context(f);
  }
};

// What every movie is encoded with, shared with FfmpegToolArgs. A fixed number of x264 threads:
// its output depends on the thread count, so leaving it to the machine's core count would make
// the same movie differ between machines (and its memory grow with the cores). 3 is what x264
// picks on two cores.
constexpr char kCodec[] = "libx264";
constexpr int kX264Threads = 3;
constexpr int kKeyframeSeconds = 2;  // for seeking

const AVCodec* FindEncoder() {
  const AVCodec* codec = Ffmpeg().avcodec_find_encoder_by_name(kCodec);
  if (!codec) {
    throw SystemError(
        "cannot encode movies: FFmpeg's libavcodec has no libx264 encoder (Debian's libavcodec59 "
        "has one; a build without it does not)");
  }
  return codec;
}

}  // namespace

void CheckEncoderAvailable() {
  FindEncoder();
}

struct VideoEncoder::Impl {
  std::string path, temp_path;
  int temp_handle = 0;  // in util/temp_registry, so a stop signal removes the file
  int width = 0, height = 0, fps = 0;
  std::unique_ptr<AVFormatContext, FormatDeleter> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  AVStream* stream = nullptr;
  long long next_pts = 0;
  bool finished = false;
  YuvFrameTap tap;
  double seconds_convert = 0, seconds_encode = 0;

  // Sends `f` (nullptr flushes) and writes every packet the encoder has ready.
  void Encode(AVFrame* f) {
    int ret = Ffmpeg().avcodec_send_frame(codec.get(), f);
    if (ret < 0) throw SystemError("encoding '" + path + "' failed: " + AvError(ret));
    while (true) {
      ret = Ffmpeg().avcodec_receive_packet(codec.get(), packet.get());
      if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
      if (ret < 0) throw SystemError("encoding '" + path + "' failed: " + AvError(ret));
      // x264 leaves durations at 0, which would make the file one frame short.
      packet->duration = 1;
      Ffmpeg().av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      ret = Ffmpeg().av_interleaved_write_frame(format.get(), packet.get());
      if (ret < 0) throw SystemError("writing '" + path + "' failed: " + AvError(ret));
    }
  }
};

const std::vector<std::string>& X264Presets() {
  static const std::vector<std::string> presets = {"ultrafast", "superfast", "veryfast",
                                                   "faster",    "fast",      "medium",
                                                   "slow",      "slower",    "veryslow"};
  return presets;
}

VideoEncoder::VideoEncoder(const std::string& path, int width, int height,
                           const EncoderSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const int fps = settings.fps;
  const auto& presets = X264Presets();
  if (std::find(presets.begin(), presets.end(), settings.preset) == presets.end()) {
    throw InputError("--preset '" + settings.preset +
                     "': not an x264 preset (ultrafast to veryslow)");
  }
  if (settings.crf < 0 || settings.crf > 51) throw InputError("--crf must be between 0 and 51");
  m.path = path;
  m.width = width;
  m.height = height;
  m.fps = fps;
  if (width % 2 != 0 || height % 2 != 0) {
    throw InputError("movie size " + std::to_string(width) + "x" + std::to_string(height) +
                     ": yuv420p needs even width and height");
  }
  if (fps < 1 || fps > 240) throw InputError("--fps must be between 1 and 240");
  CheckOutputPath(path, "movie");
  Ffmpeg().av_log_set_level(AV_LOG_ERROR);  // libx264's statistics are noise on a terminal
  m.temp_path = path + ".partial." + std::to_string(::getpid()) + ".mp4";

  AVFormatContext* format = nullptr;
  int ret = Ffmpeg().avformat_alloc_output_context2(&format, nullptr, "mp4", m.temp_path.c_str());
  if (ret < 0 || !format) throw SystemError("cannot set up MP4 output: " + AvError(ret));
  m.format.reset(format);
  const AVCodec* codec = FindEncoder();
  m.stream = Ffmpeg().avformat_new_stream(format, nullptr);
  m.codec.reset(Ffmpeg().avcodec_alloc_context3(codec));
  AVCodecContext* c = m.codec.get();
  c->width = width;
  c->height = height;
  c->time_base = AVRational{1, fps};
  c->framerate = AVRational{fps, 1};
  c->gop_size = kKeyframeSeconds * fps;
  c->thread_count = kX264Threads;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  if (format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  Ffmpeg().av_opt_set(c->priv_data, "preset", settings.preset.c_str(), 0);
  Ffmpeg().av_opt_set(c->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
  ret = Ffmpeg().avcodec_open2(c, codec, nullptr);
  if (ret < 0) throw SystemError("cannot open the H.264 encoder: " + AvError(ret));
  ret = Ffmpeg().avcodec_parameters_from_context(m.stream->codecpar, c);
  if (ret < 0) throw SystemError("cannot set stream parameters: " + AvError(ret));
  m.stream->time_base = c->time_base;

  m.frame.reset(Ffmpeg().av_frame_alloc());
  m.frame->format = c->pix_fmt;
  m.frame->width = width;
  m.frame->height = height;
  ret = Ffmpeg().av_frame_get_buffer(m.frame.get(), 0);
  if (ret < 0) throw SystemError("cannot allocate a video frame: " + AvError(ret));
  m.packet.reset(Ffmpeg().av_packet_alloc());

  // Created and registered together, so a Ctrl-C that removes every temporary cannot fall
  // between the two and leave it behind.
  m.temp_handle = CreateRegisteredTemp([&] {
    ret = Ffmpeg().avio_open(&format->pb, m.temp_path.c_str(), AVIO_FLAG_WRITE);
    if (ret < 0) throw InputError("cannot create '" + m.temp_path + "': " + AvError(ret));
    return m.temp_path;
  });
  AVDictionary* options = nullptr;
  Ffmpeg().av_dict_set(&options, "movflags", "+faststart", 0);
  ret = Ffmpeg().avformat_write_header(format, &options);
  Ffmpeg().av_dict_free(&options);
  if (ret < 0) throw SystemError("cannot write the MP4 header: " + AvError(ret));
}

VideoEncoder::~VideoEncoder() {
  if (impl_ && !impl_->finished && !impl_->temp_path.empty()) {
    impl_->format.reset();
    std::remove(impl_->temp_path.c_str());
  }
  if (impl_ && impl_->temp_handle != 0) UnregisterTemp(impl_->temp_handle);
}

long long VideoEncoder::frames() const {
  return impl_->next_pts;
}
int VideoEncoder::width() const {
  return impl_->width;
}
int VideoEncoder::height() const {
  return impl_->height;
}

void VideoEncoder::Add(const Image& image) {
  Impl& m = *impl_;
  if (image.width != m.width || image.height != m.height) {
    throw SystemError("frame size does not match the movie");
  }
  const auto start = Clock::now();
  int ret = Ffmpeg().av_frame_make_writable(m.frame.get());
  if (ret < 0) throw SystemError("video frame not writable: " + AvError(ret));
  RgbaToYuv420(image.rgba.data(), 4 * m.width, m.width, m.height, m.frame->data[0],
               m.frame->linesize[0], m.frame->data[1], m.frame->linesize[1], m.frame->data[2],
               m.frame->linesize[2]);
  const auto converted = Clock::now();
  if (m.tap) m.tap(m.frame->data, m.frame->linesize);
  m.frame->pts = m.next_pts++;
  m.Encode(m.frame.get());
  const auto encoded = Clock::now();
  m.seconds_convert += SecondsBetween(start, converted);
  m.seconds_encode += SecondsBetween(converted, encoded);
}

void VideoEncoder::AddYuv(const uint8_t* const planes[3], const int strides[3]) {
  Impl& m = *impl_;
  if (m.tap) m.tap(planes, strides);
  const auto start = Clock::now();
  int ret = Ffmpeg().av_frame_make_writable(m.frame.get());
  if (ret < 0) throw SystemError("video frame not writable: " + AvError(ret));
  for (int p = 0; p < 3; ++p) {
    const int rows = p == 0 ? m.height : m.height / 2;
    const int bytes = p == 0 ? m.width : m.width / 2;
    for (int y = 0; y < rows; ++y) {
      std::memcpy(m.frame->data[p] + static_cast<ptrdiff_t>(y) * m.frame->linesize[p],
                  planes[p] + static_cast<ptrdiff_t>(y) * strides[p], bytes);
    }
  }
  m.frame->pts = m.next_pts++;
  m.Encode(m.frame.get());
  m.seconds_encode += SecondsSince(start);
}

void VideoEncoder::set_yuv_tap(YuvFrameTap tap) {
  impl_->tap = std::move(tap);
}

double VideoEncoder::seconds_convert() const {
  return impl_->seconds_convert;
}
double VideoEncoder::seconds_encode() const {
  return impl_->seconds_encode;
}

std::vector<std::string> FfmpegToolArgs(const EncoderSettings& settings, int width, int height,
                                        const std::string& input_pixel_format,
                                        const std::string& out) {
  // The same as the constructor's codec context: pix_fmt, colour tags (BT.709, limited range),
  // gop_size, thread_count and the private options preset and crf.
  return {"ffmpeg",
          "-loglevel",
          "error",
          "-y",
          "-f",
          "rawvideo",
          "-pix_fmt",
          input_pixel_format,
          "-s",
          std::to_string(width) + "x" + std::to_string(height),
          "-r",
          std::to_string(settings.fps),
          "-i",
          "-",
          "-c:v",
          kCodec,
          "-preset",
          settings.preset,
          "-crf",
          std::to_string(settings.crf),
          "-threads",
          std::to_string(kX264Threads),
          "-g",
          std::to_string(kKeyframeSeconds * settings.fps),
          "-pix_fmt",
          "yuv420p",
          "-colorspace",
          "bt709",
          "-color_primaries",
          "bt709",
          "-color_trc",
          "bt709",
          "-color_range",
          "tv",
          "-movflags",
          "+faststart",
          out};
}

void VideoEncoder::Finish() {
  Impl& m = *impl_;
  const auto start = Clock::now();
  m.Encode(nullptr);
  m.seconds_encode += SecondsSince(start);
  int ret = Ffmpeg().av_write_trailer(m.format.get());
  if (ret < 0) throw SystemError("writing the MP4 trailer failed: " + AvError(ret));
  m.format.reset();  // closes the file
  CommitTemp([&] {
    if (std::rename(m.temp_path.c_str(), m.path.c_str()) != 0) {
      std::remove(m.temp_path.c_str());
      throw FileError("cannot rename the finished movie to '" + m.path + "'");
    }
    m.finished = true;
  });
}

}  // namespace hexgait
