// A gait movie as its options describe it (`render`, `movie`, `repertoire --movie`, Python's
// render_movie): the checks of every option, and the writing of one MP4, simulation -> render ->
// encode, with a progress bar on a terminal.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "encode/video_encoder.h"
#include "movie/movie_maker.h"
#include "run/compare_request.h"
#include "run/scene.h"
#include "run/view_request.h"

namespace hexgait {

// Marks a folder of frames `--frames` wrote, so the next movie may replace it.
inline constexpr const char* kFramesMarker = ".hexgait-frames";

struct MovieRequest {
  double time = kPaperDuration;
  std::string size = "1280x720";
  int fps = 30;
  double speed = 0;  // 0: one gait cycle per second of video
  int msaa = 0;
  std::string preset = "veryfast";  // x264
  int crf = 20;
  bool overlay = false, no_shadow = false, no_caption = false;
  std::string frames_dir;  // also write every frame as a PNG into this folder, replaced whole
  ViewRequest view;        // --view, --camera, --track, --cues
  // The options' names in messages, where a command spells them otherwise (repertoire's
  // --movie-time, --movie-size, --movie-cues).
  std::string time_flag = "--time", size_flag = "--size", cues_flag = "--cues";
};

// Range-checks every option (throws InputError naming the flag) and returns the settings they
// describe.
MovieSettings MakeMovieSettings(const MovieRequest& request, const SceneOptions& scene);
// Refuses a movie of more than kMaxMovieFrames frames (run/work_size.h) unless --allow-long:
// the frame count needs the program's cycle period, so this runs once the scene is loaded.
void RefuseLongMovieSettings(const MovieRequest& request, const MovieSettings& settings,
                             double cycle_period, bool allow_long);

// Writes one MP4 (atomically, through VideoEncoder) of `panels` stacked on one clock;
// `frames_dir`, when given, also gets every frame as a PNG. Needs no
// GL context of the caller's: it makes none (RenderGaitMovie does).
// `on_frame`, when given, is called after each frame (it may throw to end the movie, which is
// then removed): the command draws its progress bar from it; a library never draws.
MovieStats WriteMovie(const std::string& path, const Scene& scene,
                      const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                      const std::string& frames_dir = "", const Progress& on_frame = {});

// One genome's gait movie, what `render` and Python's render_movie make: a GL context, one
// panel named `label`, and a diverged run reported with the largest stable step (InputError; no
// file is left).
MovieStats RenderGaitMovie(const std::string& path, const Scene& scene, const Genome& genome,
                           const std::string& label, const MovieSettings& settings,
                           const std::string& frames_dir = "", const Progress& on_frame = {});

// `hexgait render` and Python's render_movie: one genome's gait movie written to `out`.
struct GaitMovieFile {
  SceneOptions scene;
  GenomeChoice genome;
  MovieRequest movie;
  std::string out = "out/gait.mp4";
  std::string out_flag = "--out";  // how messages name `out` (Python: "path")
  std::string expect;              // --expect: the approved movie the written one must match
};
struct GaitMovieWritten {
  MovieStats stats;
  MovieSettings settings;
  std::string label;  // the genome's name
  Scene scene;        // what the movie shows, for the caller's report of the run
  std::optional<CompareResult> expected;  // with --expect
};
// Every check before any work, in this order: the options, the inputs and the output (its
// extension, its folder), the scene, the movie's length (kMaxMovieFrames unless --allow-long),
// the genome, and what the movie needs to be drawn and encoded; then the movie (RenderGaitMovie).
GaitMovieWritten WriteGaitMovie(const GaitMovieFile& request, const Progress& on_frame = {});

// The encoder's part of the settings: frame rate, x264 preset and CRF.
EncoderSettings EncoderSettingsOf(const MovieSettings& settings);

}  // namespace hexgait
