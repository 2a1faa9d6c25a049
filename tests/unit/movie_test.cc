// Writes a short movie with VideoEncoder, decodes it with libavformat/libavcodec, and checks
// what a player would see: frame count, size, frame rate, duration, and the pixels.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "encode/encoder_thread.h"
#include "encode/video_encoder.h"
#include "encode/video_reader.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "image/image_compare.h"
#include "motor/assets.h"
#include "motor/leg_targets.h"
#include "movie/movie_maker.h"
#include "render/gl_context.h"
#include "sim/evaluate.h"
#include "util/error.h"

namespace hexgait {
namespace {

EncoderSettings Fps(int fps) {
  EncoderSettings settings;
  settings.fps = fps;
  return settings;
}

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
  int first_luma = -1;        // Y of the centre pixel of the first frame
  std::vector<uint8_t> luma;  // the Y plane of frame `keep_frame`, width x height
};

Decoded Decode(const std::string& path, int keep_frame = -1) {
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
      if (out.frames == 0) {
        out.first_luma =
            frame->data[0][(frame->height / 2) * frame->linesize[0] + frame->width / 2];
      }
      if (out.frames == keep_frame) {
        for (int y = 0; y < frame->height; ++y) {
          const uint8_t* row = frame->data[0] + y * frame->linesize[0];
          out.luma.insert(out.luma.end(), row, row + frame->width);
        }
      }
      ++out.frames;
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
    VideoEncoder encoder(path, 64, 48, Fps(25));
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

// What `hexgait compare` reads: a movie back as RGBA frames, in order and complete, in the
// colours that were encoded (the inverse of the encoder's BT.709 conversion; a wrong matrix or
// range would move these colours by tens of levels).
TEST(VideoReader, ReadsBackTheEncodedFramesAndColours) {
  const std::string path = testing::TempDir() + "/hexgait_reader_test.mp4";
  const uint8_t colours[3][3] = {{200, 200, 200}, {220, 40, 30}, {30, 90, 210}};
  {
    VideoEncoder encoder(path, 64, 48, Fps(25));
    for (int i = 0; i < 30; ++i) {
      const uint8_t* c = colours[i / 10];
      encoder.Add(Solid(64, 48, c[0], c[1], c[2]));
    }
    encoder.Finish();
  }
  VideoReader reader(path);
  EXPECT_EQ(reader.width(), 64);
  EXPECT_EQ(reader.height(), 48);
  Image frame;
  int frames = 0;
  while (reader.Next(&frame)) {
    const uint8_t* c = colours[std::min(frames / 10, 2)];
    const ImageDifference d =
        CompareImages(Solid(64, 48, c[0], c[1], c[2]), frame, ImageTolerance{4, 0});
    EXPECT_TRUE(d.within) << "frame " << frames << ": largest change " << d.max_difference;
    ++frames;
  }
  EXPECT_EQ(frames, 30);
  EXPECT_FALSE(reader.Next(&frame));
  std::filesystem::remove(path);
}

// A movie cut short (a copy interrupted, a download stopped): one error naming the file and
// FFmpeg's reason, and nothing from FFmpeg's own log (a line or more per damaged packet).
TEST(VideoReader, AMovieCutShortIsOneErrorWithFfmpegsReason) {
  const std::string path = testing::TempDir() + "/hexgait_cut_short.mp4";
  {
    VideoEncoder encoder(path, 64, 48, Fps(25));
    uint32_t noise = 12345;  // frames that do not compress away, so the cut falls in the video
    for (int i = 0; i < 20; ++i) {
      Image frame = Solid(64, 48, 0, 0, 0);
      for (size_t k = 0; k < frame.rgba.size(); k += 4) {
        noise = noise * 1664525u + 1013904223u;
        frame.rgba[k] = frame.rgba[k + 1] = frame.rgba[k + 2] = static_cast<uint8_t>(noise >> 24);
      }
      encoder.Add(frame);
    }
    encoder.Finish();
  }
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  testing::internal::CaptureStderr();
  std::string error;
  try {
    VideoReader reader(path);
    Image frame;
    while (reader.Next(&frame)) {
    }
  } catch (const InputError& e) {
    error = e.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_NE(error.find(path + ": corrupt video stream ("), std::string::npos) << error;
  std::filesystem::remove(path);
}

TEST(VideoReader, RefusesAFileThatIsNotAMovie) {
  const std::string path = testing::TempDir() + "/hexgait_not_a_movie.mp4";
  std::ofstream(path) << "not a movie";
  EXPECT_THROW(VideoReader{path}, InputError);
  std::filesystem::remove(path);
}

TEST(VideoEncoder, LeavesNoFileWhenNotFinished) {
  const std::string path = testing::TempDir() + "/hexgait_unfinished.mp4";
  std::filesystem::remove(path);
  {
    VideoEncoder encoder(path, 64, 48, Fps(25));
    encoder.Add(Solid(64, 48, 0, 0, 0));
    // destroyed without Finish(), as when an error interrupts a render
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  for (const auto& entry : std::filesystem::directory_iterator(testing::TempDir())) {
    EXPECT_EQ(entry.path().filename().string().find("hexgait_unfinished.mp4.partial"),
              std::string::npos);
  }
}

TEST(VideoEncoder, RejectsUnknownPresetsAndCrf) {
  EncoderSettings settings;
  settings.preset = "warp";
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/preset.mp4", 64, 48, settings), InputError);
  settings.preset = "ultrafast";
  settings.crf = 52;
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/crf.mp4", 64, 48, settings), InputError);
}

TEST(VideoEncoder, RejectsOddSizes) {
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/odd.mp4", 63, 48, Fps(25)), InputError);
  EXPECT_THROW(VideoEncoder(testing::TempDir() + "/fps.mp4", 64, 48, Fps(0)), InputError);
}

// The ffmpeg tool's baseline in `hexgait bench movie` encodes with the settings given, not
// with fixed ones: each flag's value follows the struct.
TEST(VideoEncoder, FfmpegToolArgsFollowTheSettings) {
  EncoderSettings settings;
  settings.fps = 24;
  settings.preset = "slow";
  settings.crf = 28;
  const std::vector<std::string> args = FfmpegToolArgs(settings, 320, 180, "rgba", "out.mp4");
  ASSERT_FALSE(args.empty());
  EXPECT_EQ(args.front(), "ffmpeg");
  EXPECT_EQ(args.back(), "out.mp4");
  const auto value = [&](const std::string& flag, int nth = 0) {
    for (size_t i = 0; i + 1 < args.size(); ++i) {
      if (args[i] == flag && nth-- == 0) return args[i + 1];
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("-preset"), "slow");
  EXPECT_EQ(value("-crf"), "28");
  EXPECT_EQ(value("-r"), "24");
  EXPECT_EQ(value("-g"), "48");  // a keyframe every 2 s
  EXPECT_EQ(value("-c:v"), "libx264");
  EXPECT_EQ(value("-threads"), "3");
  EXPECT_EQ(value("-s"), "320x180");
  EXPECT_EQ(value("-pix_fmt", 0), "rgba");     // the input
  EXPECT_EQ(value("-pix_fmt", 1), "yuv420p");  // the output
  settings.preset = "ultrafast";
  settings.crf = 0;
  const std::vector<std::string> other = FfmpegToolArgs(settings, 320, 180, "rgba", "out.mp4");
  EXPECT_NE(std::find(other.begin(), other.end(), "ultrafast"), other.end());
  EXPECT_EQ(std::find(other.begin(), other.end(), "slow"), other.end());
}

std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Encoding on a worker thread changes when frames are encoded, never what is written.
TEST(EncoderThread, WritesTheSameBytesAsDirectEncoding) {
  const std::string direct = testing::TempDir() + "/hexgait_direct.mp4";
  const std::string threaded = testing::TempDir() + "/hexgait_threaded.mp4";
  std::vector<Image> frames;
  for (int i = 0; i < 30; ++i) frames.push_back(Solid(64, 48, 8 * i, 255 - 8 * i, 100));
  {
    VideoEncoder encoder(direct, 64, 48, Fps(25));
    for (const Image& f : frames) encoder.Add(f);
    encoder.Finish();
  }
  {
    VideoEncoder encoder(threaded, 64, 48, Fps(25));
    EncoderThread thread(encoder, 2);
    for (const Image& f : frames) thread.Add(f);
    thread.Finish();
    EXPECT_EQ(encoder.frames(), 30);
  }
  EXPECT_EQ(FileBytes(direct), FileBytes(threaded));
  std::filesystem::remove(direct);
  std::filesystem::remove(threaded);
}

TEST(EncoderThread, ReportsAnEncoderErrorAndLeavesNoFile) {
  const std::string path = testing::TempDir() + "/hexgait_thread_error.mp4";
  std::filesystem::remove(path);
  VideoEncoder encoder(path, 64, 48, Fps(25));
  // The tap runs on the worker, just before encoding: its error is the worker's error.
  int taps = 0;
  encoder.set_yuv_tap([&](const uint8_t* const*, const int*) {
    if (++taps == 3) throw InputError("writing the movie failed");
  });
  EncoderThread thread(encoder, 2);
  EXPECT_THROW(
      {
        for (int i = 0; i < 10; ++i) thread.Add(Solid(64, 48, 0, 0, 0));
        thread.Finish();
      },
      InputError);
  EXPECT_EQ(taps, 3);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(EncoderThread, RefusesAFrameOfTheWrongSize) {
  const std::string path = testing::TempDir() + "/hexgait_thread_size.mp4";
  std::filesystem::remove(path);
  {
    VideoEncoder encoder(path, 64, 48, Fps(25));
    EncoderThread thread(encoder, 2);
    thread.Add(Solid(64, 48, 0, 0, 0));
    EXPECT_THROW(thread.Add(Solid(32, 32, 0, 0, 0)), SystemError);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

struct LumaError {
  double mean = 0;
  int p99 = 0;
};

LumaError CompareLuma(const Image& rendered, const std::vector<uint8_t>& luma) {
  std::vector<int> errors;
  double sum = 0;
  for (size_t p = 0; p < luma.size(); ++p) {
    const double r = rendered.rgba[4 * p], g = rendered.rgba[4 * p + 1],
                 b = rendered.rgba[4 * p + 2];
    const double y = 16.0 + 219.0 * (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0;
    const int e = static_cast<int>(std::lround(std::fabs(y - luma[p])));
    errors.push_back(e);
    sum += e;
  }
  std::sort(errors.begin(), errors.end());
  return {sum / static_cast<double>(errors.size()), errors[errors.size() * 99 / 100]};
}

// A real gait movie through the whole pipeline, decoded as a player would: the frame count the
// movie loop promised, the size and rate, and a decoded frame that matches the rendered one.
TEST(GaitMovie, DecodesToTheRenderedFrames) {
  std::string error;
  const auto context = GlContext::Create(&error);
  if (!context) GTEST_SKIP() << "no GL context: " << error;
  const CreatureModel model = LoadCreatureOrDefault("");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  MovieSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.fps = 24;
  settings.run.duration = 80;
  const MoviePanel panel{
      "unoptimized",
      PerturbedRestLengths(model, program, Genome(MakeGenomeLayout(model, program, false)))};
  const std::string path = testing::TempDir() + "/hexgait_gait_movie.mp4";
  const long long expected_frames = MovieFrameCount(settings, program.cycle_period);
  const int kept = static_cast<int>(expected_frames / 2);
  Image rendered, previous;
  {
    VideoEncoder encoder(path, settings.width, settings.height, Fps(settings.fps));
    EncoderThread thread(encoder);
    long long index = 0;
    MakeMovie(model, program, {panel}, settings, [&](const Image& frame) {
      if (index == kept - 1) previous = frame;
      if (index++ == kept) rendered = frame;
      thread.Add(frame);
    });
    thread.Finish();
  }
  const Decoded d = Decode(path, kept);
  EXPECT_EQ(d.frames, expected_frames);
  EXPECT_EQ(d.width, 320);
  EXPECT_EQ(d.height, 240);
  EXPECT_NEAR(d.fps, 24.0, 1e-9);
  EXPECT_NEAR(d.duration, static_cast<double>(expected_frames) / 24.0, 0.05);
  ASSERT_EQ(d.luma.size(), size_t{320 * 240});
  // Compare luma with the rendered frame's BT.709 limited-range luma. Tolerance from
  // measurement at this size: H.264 at CRF 20 gives a mean error of about 1.8 levels and a 99th
  // percentile of 16 (the small caption text is what costs most); the frame one step of the
  // movie earlier, which a timing or ordering bug would deliver, differs by several times more.
  const LumaError right = CompareLuma(rendered, d.luma);
  const LumaError wrong = CompareLuma(previous, d.luma);
  std::printf(
      "decoded frame %d vs rendered: mean %.3f, p99 %d levels; vs the frame before: mean "
      "%.3f, p99 %d\n",
      kept, right.mean, right.p99, wrong.mean, wrong.p99);
  EXPECT_LT(right.mean, 3.0);
  EXPECT_LT(right.p99, 24);
  EXPECT_GT(wrong.p99, 24);
  std::filesystem::remove(path);
}

// A movie is one run of the simulation, never restarted between frames: for every integrator
// (Verlet and RK4 carry data from step to step) and a frame spacing of 37 steps, which is not a
// multiple of the fall check's 40, it ends exactly where `simulate`'s uninterrupted run ends,
// bit for bit, fall included. Restarting the run at every frame fails this test.
class GaitMovieRun : public testing::TestWithParam<IntegratorKind> {};

TEST_P(GaitMovieRun, EndsWhereTheUninterruptedRunEnds) {
  std::string error;
  const auto context = GlContext::Create(&error);
  if (!context) GTEST_SKIP() << "no GL context: " << error;
  const CreatureModel model = LoadCreatureOrDefault("");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  MovieSettings settings;
  settings.width = 32;
  settings.height = 24;
  settings.caption = false;
  settings.run.integrator = GetParam();
  // Past the unoptimized program's fall, and not whole frames. Implicit Euler's damping keeps
  // the creature up, so it gets a fifth of that (still hundreds of frames): each of its steps
  // solves a linear system, and at 250 it took a sixth of the sanitized unit tests' time.
  settings.run.duration = GetParam() == IntegratorKind::kImplicitEuler ? 50.0 : 250.0;
  settings.fps = 30;
  settings.speed = 37 * settings.fps * settings.run.dt;
  ASSERT_EQ(MovieStepsPerFrame(settings, program.cycle_period), 37);
  ASSERT_NE(settings.run.check_interval % 37, 0);
  const MovieStats stats =
      MakeMovie(model, program, {{"unoptimized", PerturbedRestLengths(model, program, genome)}},
                settings, [](const Image&) {});
  const RunResult whole = EvaluateGenome(model, program, genome, settings.run);
  ASSERT_EQ(stats.results.size(), 1u);
  const RunResult& movie = stats.results[0];
  // Explicit Euler's run falls, so the fall time is compared too (implicit Euler's damping
  // keeps this creature up).
  if (GetParam() == IntegratorKind::kEuler) {
    EXPECT_TRUE(whole.fell) << "the test needs a fall";
  }
  EXPECT_EQ(movie.steps, whole.steps);
  EXPECT_EQ(movie.end_time, whole.end_time);
  EXPECT_EQ(movie.distance, whole.distance);  // exact
  EXPECT_EQ(movie.fell, whole.fell);
  EXPECT_EQ(movie.fall_time, whole.fall_time);
  EXPECT_EQ(movie.fall_cycle, whole.fall_cycle);
  EXPECT_EQ(movie.min_body_height, whole.min_body_height);
  EXPECT_EQ(movie.max_tilt_degrees, whole.max_tilt_degrees);
  EXPECT_EQ(movie.mean_feet_on_ground, whole.mean_feet_on_ground);
  EXPECT_EQ(movie.feet_samples, whole.feet_samples);
  EXPECT_EQ(stats.frames, MovieFrameCount(settings, program.cycle_period));
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, GaitMovieRun,
                         testing::Values(IntegratorKind::kEuler, IntegratorKind::kSymplecticEuler,
                                         IntegratorKind::kVerlet, IntegratorKind::kRk4,
                                         IntegratorKind::kImplicitEuler),
                         [](const testing::TestParamInfo<IntegratorKind>& param) {
                           std::string name = IntegratorName(param.param);
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace hexgait
