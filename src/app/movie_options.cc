#include "app/movie_options.h"

#include <cstdio>

#include "run/work_size.h"
#include "util/process_usage.h"

namespace hexgait {

void AddMovieOptions(CLI::App* command, MovieRequest& options, bool with_frames) {
  command->add_option("--time", options.time, "Simulated time (time units)")->capture_default_str();
  command->add_option("--size", options.size, "Frame size, WIDTHxHEIGHT (even numbers)")
      ->capture_default_str();
  command->add_option("--fps", options.fps, "Frames per second (1 to 240)")->capture_default_str();
  command->add_option("--speed", options.speed,
                      "Simulated time units per second of video (default: one gait cycle per "
                      "second; at least --dt x --fps, a frame being at least one step)");
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
  AddGlOption(command);
  if (with_frames) {
    command->add_option(
        "--frames", options.frames_dir,
        "Also write every frame as a PNG into this folder (new, empty or an earlier --frames "
        "folder; replaced whole once the movie is done)");
  }
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
