// The movies a report needs, from one evolve run (or the paper's experiment evolved first): the
// unoptimised program, the evolved one, and both stacked on one clock (comparison.mp4), each
// captioned; what `hexgait movie` makes. The set is written whole or not at all.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "ga/evolution.h"
#include "run/movie_request.h"
#include "run/scene.h"
#include "util/progress.h"

namespace hexgait {

struct MovieSetSettings {
  SceneOptions scene;
  MovieRequest movie;
  std::string run_dir;  // empty: evolve with the paper's settings first
  std::string out_dir = "out";
  uint64_t seed = 1;  // of that evolution
};

// What the set reports as it goes; every member may be left empty.
struct MovieSetObserver {
  // Without a run folder: the paper's experiment is evolved first, then its genome saved.
  std::function<void(const EvolutionParams& params)> evolving;
  std::function<void(double seconds, double distance, const std::string& genome_path)> evolved;
  // Movie `index` of `count` begins; it is written (staged until the whole set is).
  std::function<void(int index, int count, const std::string& name)> movie_started;
  // After each frame of the movie being written.
  Progress frame;
  std::function<void(const std::string& path, const MovieStats& stats,
                     const MovieSettings& settings)>
      movie_written;
};

struct MovieSetOutcome {
  double seconds = 0;
  RunResult unoptimized, evolved;  // the runs comparison.mp4 shows
};

// Checks every input and output before any work, then writes OUT/unoptimized.mp4, evolved.mp4
// and comparison.mp4 (and evolved.genome when it evolved). Throws InputError on bad input or a
// diverging creature, SystemError when the renderer or encoder fails, Stopped on Ctrl-C; then
// no movie of an earlier set is replaced.
MovieSetOutcome MakeMovieSet(const MovieSetSettings& settings,
                             const MovieSetObserver& observer = {});

}  // namespace hexgait
