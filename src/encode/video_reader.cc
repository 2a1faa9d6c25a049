#include "encode/video_reader.h"

#include "encode/ffmpeg_api.h"
#include "encode/yuv_convert.h"
#include "util/error.h"

namespace hexgait {

namespace {

struct InputDeleter {
  void operator()(AVFormatContext* f) const { Ffmpeg().avformat_close_input(&f); }
};

}  // namespace

struct VideoReader::Impl {
  std::string path;
  std::unique_ptr<AVFormatContext, InputDeleter> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  int stream = -1;
  bool flushed = false;  // the end of the file was sent to the decoder

  [[noreturn]] void Fail(const std::string& what) const { throw InputError(path + ": " + what); }
  // The same with FFmpeg's reason for the failed call's code.
  [[noreturn]] void Fail(const std::string& what, int code) const {
    Fail(what + " (" + AvError(code) + ")");
  }
};

VideoReader::VideoReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  const FfmpegApi& ff = Ffmpeg();
  Impl& m = *impl_;
  m.path = path;
  // A damaged movie would otherwise have FFmpeg print a line or more per bad packet before the
  // one-line error below, which names the file and FFmpeg's reason.
  ff.av_log_set_level(AV_LOG_QUIET);
  AVFormatContext* format = nullptr;
  if (const int opened = ff.avformat_open_input(&format, path.c_str(), nullptr, nullptr);
      opened < 0) {
    m.Fail("not a movie FFmpeg can open", opened);
  }
  m.format.reset(format);
  if (const int found = ff.avformat_find_stream_info(format, nullptr); found < 0) {
    m.Fail("no stream information", found);
  }
  const AVCodec* decoder = nullptr;
  m.stream = ff.av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (m.stream < 0 || !decoder) m.Fail("no video stream FFmpeg can decode");
  m.codec.reset(ff.avcodec_alloc_context3(decoder));
  m.frame.reset(ff.av_frame_alloc());
  m.packet.reset(ff.av_packet_alloc());
  if (!m.codec || !m.frame || !m.packet) throw SystemError("out of memory opening " + path);
  if (ff.avcodec_parameters_to_context(m.codec.get(), format->streams[m.stream]->codecpar) < 0 ||
      ff.avcodec_open2(m.codec.get(), decoder, nullptr) < 0) {
    m.Fail("cannot open its video decoder");
  }
}

VideoReader::~VideoReader() = default;

int VideoReader::width() const {
  return impl_->codec->width;
}
int VideoReader::height() const {
  return impl_->codec->height;
}

bool VideoReader::Next(Image* out) {
  const FfmpegApi& ff = Ffmpeg();
  Impl& m = *impl_;
  for (;;) {
    const int received = ff.avcodec_receive_frame(m.codec.get(), m.frame.get());
    if (received == 0) break;
    if (received == AVERROR_EOF) return false;
    if (received != AVERROR(EAGAIN)) m.Fail("corrupt video stream", received);
    if (m.flushed) return false;
    // The decoder wants more input: the next packet of our stream, or the end of the file.
    int read;
    while ((read = ff.av_read_frame(m.format.get(), m.packet.get())) >= 0 &&
           m.packet->stream_index != m.stream) {
      ff.av_packet_unref(m.packet.get());
    }
    const int sent = ff.avcodec_send_packet(m.codec.get(), read >= 0 ? m.packet.get() : nullptr);
    if (read >= 0) ff.av_packet_unref(m.packet.get());
    m.flushed = read < 0;
    if (sent < 0 && sent != AVERROR_EOF) m.Fail("corrupt video stream", sent);
  }
  const AVFrame& f = *m.frame;
  if (f.format != AV_PIX_FMT_YUV420P) {
    m.Fail("its frames are not yuv420p (the pixel format hexgait writes)");
  }
  Yuv420ToRgba(f.data, f.linesize, f.width, f.height, out);
  return true;
}

}  // namespace hexgait
