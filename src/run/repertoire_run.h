// One repertoire run into a folder, what `hexgait repertoire` runs: MAP-Elites over the paper's
// genome (search/map_elites_optimizer.h) under the search driver, a repertoire of standing gaits
// binned by behaviour, resumable from its archive.json; then, optionally, the paper's GA on the
// same budget for comparison, the elites' genomes, the map, growth curves and tables
// (report/repertoire_report.h), a movie grid of chosen elites, and repertoire.json. Printing is
// the caller's, through RepertoireObserver.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ga/map_elites.h"
#include "movie/movie_maker.h"
#include "run/scene.h"
#include "search/stored_results.h"
#include "util/progress.h"

namespace hexgait {

struct RepertoireSettings {
  SceneOptions scene;
  MapElitesParams params;
  double time = kPaperDuration;
  // "auto": float with every admission confirmed in double where the batched kernels run the
  // scene (the explicit Euler integrator on flat ground) and not under mpirun, else double. "float"
  // confirms too unless no_confirm.
  std::string precision = "auto";
  bool no_confirm = false;
  // What the run writes besides its archive, recorded in its folder (outputs.json): a resumed
  // run writes what it was started for, except what a flag given with --resume changes.
  int ga_population = 0;  // 0: no comparison
  int showcase = 6;
  std::string movie_size = "1920x1080";
  std::string movie_cues = "swing,strip";
  double movie_time = kPaperDuration;
  bool no_movie = false;
  double checkpoint_seconds = 60;
  std::string out_dir = "out/repertoire";
  std::string resume_dir;                       // continue the run whose archive.json is here
  std::vector<std::string> run_flags_given;     // run flags on the command line (not with --resume)
  std::vector<std::string> output_flags_given;  // output flags on the command line
};

// What a run reports as it goes; every member may be left empty.
struct RepertoireObserver {
  // The archive is made (or read back) and the folder taken, before the first evaluation.
  std::function<void(const MapElitesState& state, const std::string& out_dir, bool resumed)>
      started;
  // Each part as it goes: the evaluations done of the budget, the GA comparison's generations,
  // the movie grid's frames (one stage each).
  Progress progress;
  // After each batch is told (`done`: the budget is spent); `elapsed` seconds since the start.
  std::function<void(const MapElitesState& state, bool done, double elapsed)> batch;
  // After each save of archive.json.
  std::function<void()> saved;
  // A resumed archive's elites were replayed and match (search/stored_results.h).
  std::function<void(const ReplayCheck& check)> replayed;
  // The GA comparison begins.
  std::function<void(int population)> comparing;
  // The movie grid is written.
  std::function<void(const std::string& path, const MovieStats& stats,
                     const MovieSettings& settings)>
      movie_written;
};

struct RepertoireOutcome {
  std::string dir;     // the folder written, with a trailing slash
  std::string tables;  // the comparison tables of table.md, for printing
  bool movie = false;  // grid.mp4 was written
  double seconds = 0;
};

// Throws InputError on bad input (before anything is written), Stopped on Ctrl-C (the archive
// saved, with how to resume).
RepertoireOutcome RunRepertoire(const RepertoireSettings& settings,
                                const RepertoireObserver& observer = {});

// A finished repertoire read back: the scene its record names (flags may only repeat it) and its
// archive, checked against that scene. `flag` names DIR in messages ("--repertoire"). What
// `adapt` and Python's load_archive read.
struct LoadedRepertoire {
  SceneOptions options;  // the record's scene, with the flags' paths
  Scene scene;
  MapElitesState state;
};
LoadedRepertoire LoadRepertoire(const std::string& dir, const SceneOptions& flags,
                                const std::string& flag);

}  // namespace hexgait
