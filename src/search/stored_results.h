// Results a resumed run takes from its state file are checked, not trusted: the file's checksum
// guards against damage, but anyone can edit an elite's result and recompute it. Each stored
// result is replayed through the evaluator (the same bits on any thread, rank or lane count, so
// equality is exact) and must equal what the file says; past a limit, an even sample is, and the
// caller says so.
#pragma once

#include <string>
#include <vector>

#include "eval/evaluator.h"
#include "ga/map_elites.h"
#include "motor/leg_targets.h"
#include "sim/step_loop.h"

namespace hexgait {

struct StoredResult {
  std::string name;       // for the message: "the elite in cell 123"
  RestLengthTable table;  // what was simulated
  RunResult result;       // what the file says came of it
};

struct ReplayCheck {
  size_t replayed = 0;  // results simulated again, every one equal to its stored result
  size_t stored = 0;    // results in the file
  // "replayed 256 of 1843 stored elites (an even sample): every result matches"
  std::string Text(const std::string& what) const;
};

// Every elite of `archive` as a stored result, named by its cell.
std::vector<StoredResult> StoredElites(const Archive& archive, const CreatureModel& model,
                                       const MotorProgram& program);

// Replays all of `stored`, or `max_replays` of them spread evenly (the first and the last
// included) when there are more. Throws InputError naming `source`, the first result that does
// not replay and how it differs; EvaluationStopped on Ctrl-C. With `between`, the replays run in
// slices (EvaluateInSlices, `threads` the evaluator's) and `between` hears after each.
ReplayCheck ReplayStoredResults(const std::vector<StoredResult>& stored, Evaluator& evaluator,
                                const std::string& source, size_t max_replays = 256,
                                int threads = 0, const Progress& between = {});

// Results replayed on resume at most: one evaluation each, so a large archive is sampled.
inline constexpr size_t kDefaultMaxReplays = 256;

}  // namespace hexgait
