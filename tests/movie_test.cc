// Writes a short movie with VideoEncoder, decodes it with libavformat/libavcodec, and checks
// what a player would see: frame count, size, frame rate, duration, and the pixels.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <cstdio>
#include <filesystem>

#include "encode/video_encoder.h"
#include "util/error.h"

namespace hexgait {
namespace {

Image Solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.resize(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = r;
    image.rgba[i + 1] = g;
    image.rgba[i + 2] = b;
    image.rgba[i + 3] = 255;
  }
  return image;
}

struct Decoded {
  int frames = 0, width = 0, height = 0;
  double fps = 0, duration = 0;
  int first_luma = -1;  // Y of the centre pixel of the first frame
};

Decoded Decode(const std::string& path) {
  Decoded out;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return out;
  avformat_find_stream_info(format, nullptr);
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  AVStream* stream = format->streams[index];
  const AVCodec* codec = avcodec_find_decoder(stream->codecpar->codec_id);
  AVCodecContext* context = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(context, stream->codecpar);
  avcodec_open2(context, codec, nullptr);
  out.width = stream->codecpar->width;
  out.height = stream->codecpar->height;
  out.fps = av_q2d(stream->avg_frame_rate);
  out.duration = static_cast<double>(format->duration) / AV_TIME_BASE;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto drain = [&] {
    while (avcodec_receive_frame(context, frame) == 0) {
      if (out.frames++ == 0) {
        out.first_luma =
            frame->data[0][(frame->height / 2) * frame->linesize[0] + frame->width / 2];
      }
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index) {
      avcodec_send_packet(context, packet);
      drain();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(context, nullptr);
  drain();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&context);
  avformat_close_input(&format);
  return out;
}

TEST(VideoEncoder, WritesAPlayableH264Mp4) {
  const std::string path = testing::TempDir() + "/hexgait_movie_test.mp4";
  {
    VideoEncoder encoder(path, 64, 48, 25);
    for (int i = 0; i < 50; ++i) encoder.Add(Solid(64, 48, 200, 200, 200));
    encoder.Finish();
    EXPECT_EQ(encoder.frames(), 50);
  }
  const Decoded d = Decode(path);
  EXPECT_EQ(d.frames, 50);
  EXPECT_EQ(d.width, 64);
  EXPECT_EQ(d.height, 48);
  EXPECT_NEAR(d.fps, 25.0, 1e-9);
  EXPECT_NEAR(d.duration, 2.0, 0.05);  // 50 frames at 25 fps
  // BT.709 limited range: Y = 16 + 219 * (200 / 255) = 187.8 for grey 200; H.264 at CRF 20
  // keeps a flat frame within a couple of levels.
  EXPECT_NEAR(d.first_luma, 188, 3);
  std::filesystem::remove(path);
}

TEST(VideoEncoder, LeavesNoFileWhenNotFinished) {
  const std::string path = testing::TempDir() + "/hexgait_unfinished.mp4";
  std::filesystem::remove(path);
  {
    VideoEncoder encoder(path, 64, 48, 25);
    encoder.Add(Solid(64, 48, 0, 0, 0));
    // destroyed without Finish(), as when an error interrupts a render
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& entry : std::filesystem::directory_iterator(testing::TempDir())) {
    EXPECT_EQ(entry.path().filename().string().find("hexgait_unfinished.mp4.partial"),
              std::string::npos);
  }
}

TEST(VideoEncoder, RejectsOddSizes) {
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/odd.mp4", 63, 48, 25), InputError);
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/fps.mp4", 64, 48, 0), InputError);
}

}  // namespace
}  // namespace hexgait
