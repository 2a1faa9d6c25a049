// `hexgait adapt` and Python's adapt(): Intelligent Trial and Error (adapt/trial_and_error.h)
// over a finished repertoire's elites on a damaged creature. A trial is one simulation of an
// elite's genome on the damaged creature, in double, as `simulate --damage` runs it, with the
// repertoire's own run settings (its time, step, integrator, and the end at a fall), so a
// trial's distance is measured as the repertoire measured the prior.
//
// For the figure and the comparisons (never for the choice of trials) every elite is also run
// once on the damaged creature: the best elite there is what adaptation could find at best.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "adapt/trial_and_error.h"
#include "run/movie_request.h"
#include "run/scene.h"
#include "search/stored_results.h"
#include "sim/step_loop.h"
#include "util/output.h"

namespace hexgait {

struct AdaptRequest {
  std::string repertoire_dir;             // a finished `hexgait repertoire` folder (archive.json)
  std::string damage;                     // --damage: required
  std::string creature_path, motor_path;  // empty: the repertoire's recorded creature
  TrialAndErrorParams params;
  uint64_t seed = 1;  // the random-elites comparison's draw
  int threads = 0;    // 0: every core, for the run of every elite
  // Injuries simulated on every leg (--library: DefaultDamageLibraryKinds; empty: none): after
  // every trial the loop's prior is the damage whose gaits look most like the trials'
  // (adapt/trial_and_error.h), the elites run on its creatures as the loop reads them. The
  // damage adapted to is left out if it is among them: a robot does not know its damage, and a
  // library holding it would find it at once.
  std::vector<std::string> library_kinds;
  // The side-by-side movie (adapt.mp4): the damaged creature with the intact best gait and with
  // the adapted one, on one clock. Empty: none.
  std::optional<MovieRequest> movie;
  // The folder's figure will be drawn (gnuplot, found before the trials); Python's adapt()
  // draws none.
  bool figure = false;
  // Called from the calling thread between pieces of the work, each a fraction of a second:
  // slices of the run of every elite, each trial, each generation of the GA comparison. What
  // the command's progress bar draws, and where Python checks for Ctrl-C; may throw to end the
  // work.
  Progress on_progress;
};

struct AdaptOutcome {
  Scene scene;                 // the damaged creature and its program
  SceneOptions scene_options;  // what loads it, with the repertoire's step and integrator
  // The intact scene the repertoire was made on, as its record says (with its fingerprint):
  // adapt.json keeps it, so a consumer of the folder knows the scene without the repertoire.
  SceneOptions repertoire_scene;
  std::string damage;  // as ParseDamage reads it back
  double time = 0;     // the repertoire's run length: every trial's
  int descriptor_dims = 0;
  std::vector<int> cells;                       // per elite: its cell in the archive
  std::vector<std::vector<double>> descriptor;  // per elite
  std::vector<double> prior;                    // per elite: its distance on the intact creature
  ReplayCheck prior_check;                      // those distances, replayed (or a sample)
  std::vector<RunResult> damaged;               // per elite: its run on the damaged creature
  std::vector<RunResult> trial_runs;            // per trial: its run (fell, diverged, ...)
  std::vector<Genome> genomes;                  // per elite
  std::vector<std::string> library;             // the library's damages, as DamageText writes
  // The elites' runs on the library's creatures the loop read, and so made (of library.size()
  // x elites: adapt/library_runs.h).
  long long library_runs = 0;
  TrialAndErrorResult adaptation;
  int intact_best = -1;    // the archive's best elite (its best on the intact creature)
  int damaged_best = -1;   // the best elite on the damaged creature, found by running them all
  int adapted = -1;        // the elite of the best trial
  double random_best = 0;  // the best of as many random elites as adaptation used trials
  // The paper's GA (population 4) started from the intact best gait on the damaged creature,
  // for at least as many evaluations as adaptation used trials: its best and its evaluations.
  double ga_best = 0;
  int ga_evaluations = 0;
  // With the stop rule off (--no-stop) and where it would have held: the same comparisons at
  // that many trials, so one run answers "after the stop rule" and "after N trials".
  struct AtTrials {
    int trials = 0;
    double adapted = 0;  // the best of the first `trials` trials
    double random_best = 0;
    double ga_best = 0;
    int ga_evaluations = 0;
  };
  std::optional<AtTrials> at_stop_rule;
  double seconds = 0;
  int trials() const { return static_cast<int>(adaptation.trials.size()); }
  // A trial's prior (Trial::prior): "intact", the recorded distances, or a library damage.
  std::string PriorName(int member) const;
  // Elites whose run on the damaged creature diverged: their distance counts as 0, and they are
  // counted apart, never as fallen or standing.
  int diverged() const;
};

// Loads the repertoire (refusing an unfinished one, or one of another creature or program),
// damages the creature and adapts. Checks everything known at the start (the options, the
// repertoire, the damage, the movie's settings and GL backend) before the first simulation.
// Throws InputError for bad input, and when every elite falls or diverges on the damaged
// creature (there is nothing to adapt to).
AdaptOutcome AdaptToDamage(const AdaptRequest& request);

// The folder adapt writes, taken before the work: new, empty or an earlier adapt folder, in a
// writable folder (InputError or FileError naming `--out` otherwise), and locked until written.
std::unique_ptr<AtomicDir> TakeAdaptFolder(const std::string& out_dir);

// Writes the folder whole (replacing an earlier adapt folder): trials.csv, elites.csv,
// adapt.json, adapted.genome, the figure adapt.png/.svg with its CSV and script, and
// adapt.mp4 when the request asks for the movie.
void WriteAdaptFolder(const AdaptRequest& request, const AdaptOutcome& outcome, AtomicDir& dir);

// `hexgait adapt`: the adaptation, written into the folder `out` (replaced whole), with its
// movie unless `no_movie`.
struct AdaptFile {
  AdaptRequest request;
  std::string out = "out/adapt";
  bool no_movie = false;
  MovieRequest movie;  // its flags are named --movie-time, --movie-size, --movie-cues
};
// Every check before any work, in this order: the repertoire against the output folder, the
// movie's options, the folder taken (a bad --out is found in milliseconds, not after the
// trials); then AdaptToDamage (which checks the repertoire, the damage and what the figure and
// movie need before its trials) and the folder written.
AdaptOutcome AdaptToFolder(AdaptFile file);

}  // namespace hexgait
