#include "app/movie_options.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/progress.h"
#include "app/work_size.h"
#include "encode/encoder_thread.h"
#include "encode/video_encoder.h"
#include "render/png_io.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {

void AddMovieOptions(CLI::App* command, MovieCliOptions& options, bool with_frames) {
  command->add_option("--time", options.time, "Simulated time (time units)")->capture_default_str();
  command->add_option("--size", options.size, "Frame size, WIDTHxHEIGHT (even numbers)")
      ->capture_default_str();
  command->add_option("--fps", options.fps, "Frames per second (1 to 240)")->capture_default_str();
  command->add_option("--speed", options.speed,
                      "Simulated time units per second of video (default: one gait cycle per "
                      "second)");
  command
      ->add_option("--msaa", options.msaa,
                   "Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8; 4 looks smoother "
                   "and renders about 3x slower")
      ->capture_default_str();
  command
      ->add_option("--preset", options.preset,
                   "x264 speed preset, ultrafast to veryslow: slower presets make smaller files "
                   "of the same quality and take longer (docs/speed.md)")
      ->capture_default_str();
  command
      ->add_option("--crf", options.crf,
                   "x264 quality, 0 (lossless) to 51: lower is better and larger; 18-23 is "
                   "visually clean")
      ->capture_default_str();
  command->add_flag("--overlay", options.overlay,
                    "Draw springs and particles over the polygons (as in the paper's Figure 1)");
  command->add_flag("--no-shadow", options.no_shadow, "Do not draw the shadow on the ground");
  command->add_flag("--no-caption", options.no_caption,
                    "Do not draw the caption (name, time, gait cycle, distance)");
  AddViewOptions(command, options.view, true);
  if (with_frames) {
    command->add_option("--frames", options.frames_dir,
                        "Also write every frame as a PNG into this existing folder");
  }
}

MovieSettings MakeMovieSettings(const MovieCliOptions& options, const SceneOptions& scene) {
  MovieSettings settings;
  ParseSize(options.size, &settings.width, &settings.height);
  if (settings.width % 2 != 0 || settings.height % 2 != 0) {
    throw InputError("--size " + options.size + ": yuv420p needs even width and height");
  }
  if (options.fps < 1 || options.fps > 240) throw InputError("--fps must be between 1 and 240");
  if (!std::isfinite(options.speed) || options.speed < 0) {
    throw InputError("--speed must be a positive number of time units per second");
  }
  if (options.speed > 1e6) throw InputError("--speed must be at most 1e6 time units per second");
  if (options.msaa != 0 && options.msaa != 2 && options.msaa != 4 && options.msaa != 8) {
    throw InputError("--msaa must be 0, 2, 4 or 8");
  }
  const auto& presets = X264Presets();
  if (std::find(presets.begin(), presets.end(), options.preset) == presets.end()) {
    throw InputError("--preset '" + options.preset +
                     "': not an x264 preset (ultrafast to veryslow)");
  }
  if (options.crf < 0 || options.crf > 51) throw InputError("--crf must be between 0 and 51");
  if (!options.frames_dir.empty() && !std::filesystem::is_directory(options.frames_dir)) {
    throw InputError("--frames '" + options.frames_dir + "': no such folder");
  }
  settings.run = MakeRunOptions(scene, options.time);
  settings.fps = options.fps;
  settings.speed = options.speed;
  settings.msaa_samples = std::max(1, options.msaa);
  settings.preset = options.preset;
  settings.crf = options.crf;
  settings.look.overlay = options.overlay;
  settings.look.shadow = !options.no_shadow;
  settings.caption = !options.no_caption;
  settings.camera = MakeCameraSpec(options.view);
  settings.cues = MakeCueOptions(options.view);
  return settings;
}

void RefuseLongMovieSettings(const MovieCliOptions& options, const MovieSettings& settings,
                             double cycle_period, bool allow_long) {
  char what[160];
  std::snprintf(what, sizeof what, "--time %g at --speed %g and --fps %d", options.time,
                settings.speed > 0 ? settings.speed : cycle_period, options.fps);
  RefuseLongMovie(what, MovieFrameCount(settings, cycle_period), allow_long);
}

EncoderSettings EncoderSettingsOf(const MovieSettings& settings) {
  EncoderSettings encoder;
  encoder.fps = settings.fps;
  encoder.preset = settings.preset;
  encoder.crf = settings.crf;
  return encoder;
}

double PeakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

MovieStats WriteMovie(const std::string& path, const Scene& scene,
                      const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                      const std::string& frames_dir) {
  VideoEncoder encoder(path, settings.width, settings.height, EncoderSettingsOf(settings));
  EncoderThread encoder_thread(encoder);
  ProgressBar bar("rendering " + std::filesystem::path(path).filename().string());
  long long frames_written = 0;
  const FrameSink sink = [&](const Image& frame) {
    encoder_thread.Add(frame);
    if (!frames_dir.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05lld.png", frames_written++);
      WritePng(frames_dir + name, frame);
    }
  };
  const FrameProgress progress = [&](long long frame, long long total) {
    bar.Update(static_cast<double>(frame) / static_cast<double>(total),
               std::to_string(frame) + "/" + std::to_string(total) + " frames");
  };
  const auto start = std::chrono::steady_clock::now();
  MovieStats stats = MakeMovie(scene.model, scene.program, panels, settings, sink, progress);
  encoder_thread.Finish();
  stats.seconds_total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.Clear();
  stats.seconds_encode = encoder_thread.seconds_convert() + encoder.seconds_encode();
  return stats;
}

void PrintMovieSummary(const std::string& path, const MovieStats& stats,
                       const MovieSettings& settings) {
  std::printf(
      "wrote %s: %lld frames, %dx%d at %d fps (%.1f s of video) in %.1f s "
      "(simulate %.1f, render %.1f, convert+encode %.1f), peak memory %.0f MiB\n",
      path.c_str(), stats.frames, settings.width, settings.height, settings.fps,
      static_cast<double>(stats.frames) / settings.fps, stats.seconds_total, stats.seconds_simulate,
      stats.seconds_render, stats.seconds_encode, PeakMemoryMiB());
  std::fflush(stdout);
}

}  // namespace hexgait
