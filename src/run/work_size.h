// A request whose size is absurd (days of simulation from a large --time, millions of frames
// from a tiny --speed) is refused before any work, with the estimate and the flag that allows
// it. The estimates use deliberately fast costs, so only requests that surely take longer than
// an hour on any machine are refused; the constants and their sources are in
// docs/reliability.md.
#pragma once

#include <string>

#include "model/creature.h"
#include "sim/step_loop.h"

namespace hexgait {

// How a request simulates its creatures: each alone on the scalar path (simulate, still,
// render, movie, filmstrip, replay, figures, endurance) or many at once in batched lanes (evolve,
// repertoire, sweep, Python's evaluate).
enum class StepPath { kScalar, kBatched };

// The one estimate of a request's simulation time, in seconds: `runs` runs of `steps` steps
// each of `model` on `path`, shared by `workers` threads. Per-step costs measured on creatures
// up to 1,000 particles and taken 2x faster (work_size.cc), so a refused request surely takes
// longer than an hour and the estimate is within a factor of two of the measured machine.
double EstimatedSimulationSeconds(const CreatureModel& model, double runs, double steps,
                                  StepPath path, double workers = 1);

// One movie frame rendered, captioned and encoded. Measured: 17 ms at 1280x720 (`hexgait
// bench movie`, docs/speed.md); taken 8x faster, for small frames.
inline constexpr double kSecondsPerFrame = 2e-3;

// Longer than this is refused without --allow-long.
inline constexpr double kLongRunSeconds = 3600;
// A movie of more frames than this (55 minutes at 30 fps) is refused without --allow-long.
inline constexpr long long kMaxMovieFrames = 100000;

// "2.5 hours", "41 days", "1.3 years".
std::string DurationText(double seconds);

// Throws InputError "WHAT: at least DURATION of computing (more than an hour); pass
// --allow-long to run it anyway" when `seconds` exceeds kLongRunSeconds and !allow_long.
void RefuseLongRun(const std::string& what, double seconds, bool allow_long);

// The one refusal of batched evaluations (evolve, repertoire, bench scale, Python's
// evaluate): `evaluations` runs of `run` (its duration at its step) on `workers` threads, as
// "WHAT are N evaluations of S steps on W threads: at least ...".
void RefuseLongEvaluations(const std::string& what, const CreatureModel& model, double evaluations,
                           const RunOptions& run, double workers, bool allow_long);

// The same for a movie of `frames` frames above kMaxMovieFrames.
void RefuseLongMovie(const std::string& what, long long frames, bool allow_long);

// "--time 1000 at --dt 0.0025 is 400000 steps" for messages.
std::string StepsText(double time, double dt, const std::string& time_flag = "--time");

}  // namespace hexgait
