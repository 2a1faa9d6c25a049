#include "bench/movie_bench.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "encode/encoder_thread.h"
#include "motor/controller.h"
#include "render/gl_context.h"
#include "sim/step_loop.h"
#include "util/child_process.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/median.h"

namespace hexgait {
namespace {

struct Measured {
  std::vector<double> simulate_alone, movie_total, simulate, render, compose, convert, encode,
      pipe_total, encode_only;
  long long frames = 0;
  double movie_bytes = 0;
};

}  // namespace

MovieBenchReport MeasureMovie(const CreatureModel& model, const MotorProgram& program,
                              const MoviePanel& panel, const MovieBenchSettings& bench,
                              const LogLine& note) {
  auto say = [&](const std::string& line) {
    if (note) note(line);
  };
  const MovieSettings& settings = bench.movie;
  MovieBenchReport report;
  report.size = bench.size;
  report.fps = settings.fps;
  report.time_units = settings.run.duration;
  report.repeats = bench.repeats;
  report.preset = settings.preset;
  report.crf = settings.crf;
  report.ffmpeg = bench.ffmpeg;
  // 1. Peak memory of the whole `hexgait render` process, for a short and a 10x longer movie.
  report.short_time = std::min(settings.run.duration, 100.0);
  if (bench.peak_memory_of_render) {
    char line[128];
    std::snprintf(line, sizeof(line), "peak memory of 'hexgait render' (%g and %g time units)",
                  report.short_time, 10 * report.short_time);
    say(line);
    report.memory = true;
    report.peak_mib_short = bench.peak_memory_of_render(report.short_time);
    report.peak_mib_long = bench.peak_memory_of_render(10 * report.short_time);
  }
  const auto context = GlContext::CreateOrThrow("cannot render");
  // A broken pipe must be an error from fwrite, not a silent death of the benchmark.
  std::signal(SIGPIPE, SIG_IGN);

  // The movie's frames after conversion, kept from the first repeat for the encode-only
  // reference: libx264 in process on exactly these frames, with nothing else running.
  std::vector<std::vector<uint8_t>> yuv_frames;
  const EncoderSettings& encoder_settings = bench.encoder;
  Measured m;
  for (int r = 0; r < bench.repeats; ++r) {
    say("repeat " + std::to_string(r + 1) + "/" + std::to_string(bench.repeats));
    {  // 2. The same simulation with no movie.
      MotorController controller(model, program, panel.rest_lengths, settings.run.dt);
      SimState state = MakeRestState(model);
      NullObserver none;
      const auto t = Clock::now();
      Simulate(model, controller, state, settings.run, none);
      m.simulate_alone.push_back(SecondsSince(t));
    }
    {  // 3. The in-process pipeline: render -> yuv420p -> libx264 -> MP4.
      const auto t = Clock::now();
      VideoEncoder encoder(bench.movie_path, settings.width, settings.height, encoder_settings);
      if (r == 0) {
        encoder.set_yuv_tap([&](const uint8_t* const planes[3], const int strides[3]) {
          std::vector<uint8_t> yuv;
          yuv.reserve(static_cast<size_t>(settings.width) * settings.height * 3 / 2);
          for (int p = 0; p < 3; ++p) {
            const int rows = p == 0 ? settings.height : settings.height / 2;
            const int bytes = p == 0 ? settings.width : settings.width / 2;
            for (int y = 0; y < rows; ++y) {
              const uint8_t* row = planes[p] + static_cast<ptrdiff_t>(y) * strides[p];
              yuv.insert(yuv.end(), row, row + bytes);
            }
          }
          yuv_frames.push_back(std::move(yuv));
        });
      }
      EncoderThread encoder_thread(encoder);
      const MovieStats s = MakeMovie(model, program, {panel}, settings,
                                     [&](const Image& frame) { encoder_thread.Add(frame); });
      encoder_thread.Finish();
      m.movie_total.push_back(SecondsSince(t));
      m.simulate.push_back(s.seconds_simulate);
      m.render.push_back(s.seconds_render);
      m.compose.push_back(s.seconds_compose);
      m.convert.push_back(encoder_thread.seconds_convert());
      m.encode.push_back(encoder.seconds_encode());
      m.frames = s.frames;
      m.movie_bytes = static_cast<double>(std::filesystem::file_size(bench.movie_path));
    }
    {  // 4. The reference: x264 alone on the same yuv420p frames.
      const int w = settings.width, h = settings.height;
      const int strides[3] = {w, w / 2, w / 2};
      const auto t = Clock::now();
      VideoEncoder encoder(bench.reference_path, w, h, encoder_settings);
      for (const std::vector<uint8_t>& yuv : yuv_frames) {
        const uint8_t* planes[3] = {yuv.data(), yuv.data() + static_cast<size_t>(w) * h,
                                    yuv.data() + static_cast<size_t>(w) * h * 5 / 4};
        encoder.AddYuv(planes, strides);
      }
      encoder.Finish();
      m.encode_only.push_back(SecondsSince(t));
    }
    if (bench.ffmpeg) {  // 5. The same frames as raw RGBA through a pipe into the ffmpeg tool.
      const auto t = Clock::now();
      // The tool encodes with the settings this benchmark reports (preset, CRF, fps...).
      ChildProcess child(FfmpegToolArgs(encoder_settings, settings.width, settings.height, "rgba",
                                        bench.pipe_path),
                         true);
      bool ok = true;
      MakeMovie(model, program, {panel}, settings, [&](const Image& frame) {
        ok = ok && std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), child.input()) ==
                       frame.rgba.size();
      });
      if (child.Wait() != 0 || !ok) throw SystemError("the ffmpeg tool failed on the raw frames");
      m.pipe_total.push_back(SecondsSince(t));
    }
  }
  report.frames = m.frames;
  report.simulation_alone = Median(m.simulate_alone);
  report.movie_total = Median(m.movie_total);
  report.simulate = Median(m.simulate);
  report.render = Median(m.render);
  report.compose = Median(m.compose);
  report.convert = Median(m.convert);
  report.encode = Median(m.encode);
  report.encode_only = Median(m.encode_only);
  report.movie_bytes = m.movie_bytes;
  if (bench.ffmpeg) report.ffmpeg_pipe_total = Median(m.pipe_total);
  return report;
}

nlohmann::json MovieBenchReportJson(const MovieBenchReport& r) {
  const double frames = static_cast<double>(r.frames);
  nlohmann::json j;
  j["size"] = r.size;
  j["fps"] = r.fps;
  j["time_units"] = r.time_units;
  j["frames"] = r.frames;
  j["repeats"] = r.repeats;
  j["seconds_simulation_alone"] = r.simulation_alone;
  j["seconds_movie_total"] = r.movie_total;
  j["seconds_simulate_in_movie"] = r.simulate;
  j["render_fps"] = frames / r.render;
  j["caption_fps"] = frames / r.compose;
  j["convert_fps"] = frames / r.convert;
  j["encode_fps"] = frames / r.encode;
  j["preset"] = r.preset;
  j["crf"] = r.crf;
  j["movie_megabytes"] = r.movie_bytes / 1e6;
  j["seconds_x264_encode_only"] = r.encode_only;
  j["ratio_movie_to_encode_only"] = r.movie_total / r.encode_only;
  j["seconds_ffmpeg_pipe_total"] = r.ffmpeg ? nlohmann::json(r.ffmpeg_pipe_total) : nullptr;
  j["speedup_over_ffmpeg_pipe"] =
      r.ffmpeg ? nlohmann::json(r.ffmpeg_pipe_total / r.movie_total) : nullptr;
  j["peak_mib_short_movie"] = r.memory ? nlohmann::json(r.peak_mib_short) : nullptr;
  j["peak_mib_long_movie"] = r.memory ? nlohmann::json(r.peak_mib_long) : nullptr;
  return j;
}

}  // namespace hexgait
