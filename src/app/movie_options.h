// Options shared by `render` (one movie) and `movie` (the report's set): frame size, rate,
// playback speed and what is drawn; and the writing of one MP4 with a progress bar.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/view_options.h"
#include "encode/video_encoder.h"
#include "movie/movie_maker.h"

namespace hexgait {

struct MovieCliOptions {
  double time = kPaperDuration;
  std::string size = "1280x720";
  int fps = 30;
  double speed = 0;  // 0: one gait cycle per second of video
  int msaa = 0;
  std::string preset = "veryfast";  // x264
  int crf = 20;
  bool overlay = false, no_shadow = false, no_caption = false;
  std::string frames_dir;  // also write every frame as a PNG here
  ViewCliOptions view;     // --view, --camera, --track, --cues
};

// `with_frames` adds --frames (one movie per command only).
void AddMovieOptions(CLI::App* command, MovieCliOptions& options, bool with_frames);
// Range-checks every option (throws InputError) and returns the settings they describe.
MovieSettings MakeMovieSettings(const MovieCliOptions& options, const SceneOptions& scene);
// Refuses a movie of more than kMaxMovieFrames frames (app/work_size.h) unless --allow-long:
// the frame count needs the program's cycle period, so this runs once the scene is loaded.
void RefuseLongMovieSettings(const MovieCliOptions& options, const MovieSettings& settings,
                             double cycle_period, bool allow_long);

// Writes one MP4 (atomically, through VideoEncoder) of `panels` stacked on one clock, with a
// progress bar on a terminal.
MovieStats WriteMovie(const std::string& path, const Scene& scene,
                      const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                      const std::string& frames_dir = "");
// One line: the file, its frames, where the time went and the peak memory.
void PrintMovieSummary(const std::string& path, const MovieStats& stats,
                       const MovieSettings& settings);

// The encoder's part of the settings: frame rate, x264 preset and CRF.
EncoderSettings EncoderSettingsOf(const MovieSettings& settings);

// The process's peak resident memory so far, in MiB.
double PeakMemoryMiB();

}  // namespace hexgait
