// `hexgait bench movie`'s measurement: where a movie's time goes (simulation, render, colour
// conversion, encode), the whole in-process pipeline against libx264 alone on the same frames
// and against piping raw RGBA frames into the ffmpeg command-line tool, and the peak memory of
// short and long movies. Built into hexgait_bench_media, apart from hexgait_bench_lib, because
// it draws and encodes.
#pragma once

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "encode/video_encoder.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "movie/movie_maker.h"
#include "util/progress.h"

namespace hexgait {

struct MovieBenchSettings {
  MovieSettings movie;      // the movie measured: size, fps, run options, x264 preset and CRF
  EncoderSettings encoder;  // the encoder's settings of that movie
  std::string size;         // "WIDTHxHEIGHT", as reported
  int repeats = 3;          // measurements per figure; the median is reported
  // Scratch movies: the in-process one, the ffmpeg tool's and the encode-only reference.
  std::string movie_path, pipe_path, reference_path;
  bool ffmpeg = true;  // time the ffmpeg tool on the same frames (the caller found it)
  // The peak memory (MiB) of a whole `hexgait render` of `time` time units, as the command
  // measures it (a child process); empty: not measured. Called first, while this process is
  // small: a child's peak includes the highest memory its parent had reached when it forked.
  std::function<double(double time)> peak_memory_of_render;
};

struct MovieBenchReport {
  std::string size;
  int fps = 30;
  double time_units = 0;
  long long frames = 0;
  int repeats = 1;
  std::string preset;
  int crf = 20;
  // Medians, seconds.
  double simulation_alone = 0;  // the same simulation with no movie
  double movie_total = 0;       // simulation + render + caption + conversion + encode + MP4
  double simulate = 0, render = 0, compose = 0, convert = 0, encode = 0;  // inside movie_total
  double encode_only = 0;  // libx264 alone on the movie's yuv420p frames
  double movie_bytes = 0;
  bool ffmpeg = false;
  double ffmpeg_pipe_total = 0;  // the same frames as raw RGBA into the ffmpeg tool
  bool memory = false;
  double short_time = 0;  // the short memory run's time units (the long run's is 10x)
  double peak_mib_short = 0, peak_mib_long = 0;
};

// Measures `panel` on `model` running `program`; `note` hears a line as each stage starts.
// Throws as GlContext::CreateOrThrow ("cannot render") when no GL context can be made.
MovieBenchReport MeasureMovie(const CreatureModel& model, const MotorProgram& program,
                              const MoviePanel& panel, const MovieBenchSettings& settings,
                              const LogLine& note = {});

// `hexgait bench movie --json`.
nlohmann::json MovieBenchReportJson(const MovieBenchReport& report);

}  // namespace hexgait
