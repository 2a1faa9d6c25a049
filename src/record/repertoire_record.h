// repertoire.json, the record of a `hexgait repertoire` run: its settings, each method's
// result (MAP-Elites and the GA on the same budget), the showcased elites and the movie grid,
// as one type with one pair of JSON functions. `repertoire` writes it; the report page reads it.
// Files from older hexgait still read: a key it lacks keeps its default.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace hexgait {

// One search's line of the comparison (table.md's row).
struct RepertoireMethodRecord {
  std::string name;  // "MAP-Elites", "paper's GA, population 100"
  long long evaluations = 0;
  long long filled = 0;      // cells of its archive
  double qd_score = 0;       // the sum of its elites' distances
  double best_standing = 0;  // the farthest gait that stands the test; 0 when none
  double best_fitness = 0;   // the farthest of any evaluation, fallen or not
  double seconds = 0;
  long long diverged = 0;  // evaluations whose simulation diverged (neither fell nor stood)
};

// One elite of the movie grid.
struct ShowcaseRecord {
  int cell = 0;
  std::string genome;  // relative to the folder: "elites/elite-1.genome"
  double distance = 0;
  std::vector<double> duty_factors;  // one per leg
  long long found_at = 0;            // the evaluation (1-based) that found it
};

struct RepertoireMovieRecord {
  std::string file = "grid.mp4";
  double time = 0;
  long long frames = 0;
};

// How busy this process kept the machine while it searched (from its start, or its resume):
// the search's wall seconds, every thread's CPU seconds over them (busy share: cpu_seconds /
// (threads x seconds)), and the refilled lanes' steps by precision, all and those that ran a
// creature (sim/lane_refill.h's LaneSteps). Under mpirun, rank 0's process alone.
struct MachineUseRecord {
  double seconds = 0;
  double cpu_seconds = 0;
  long long float_lane_steps = 0, float_lane_steps_running = 0;
  long long double_lane_steps = 0, double_lane_steps_running = 0;
};

struct RepertoireRecord {
  std::string hexgait_version = HEXGAIT_VERSION;
  uint64_t seed = 0;  // written as a string
  // The optimizer that filled the archive and its own parameters (by its table); files before
  // CMA-MAE name none: MAP-Elites with its rates.
  std::string algorithm;
  nlohmann::json settings = nlohmann::json::object();
  std::string descriptor;
  std::vector<std::string> axes;
  int bins = 0;
  long long cells = 0;
  int threads = 0, ranks = 1;
  double time = 0, dt = 0;
  std::string precision = "double";
  std::vector<RepertoireMethodRecord> methods;  // MAP-Elites first
  std::vector<ShowcaseRecord> showcase;
  std::optional<RepertoireMovieRecord> movie;   // none with --no-movie
  std::optional<MachineUseRecord> machine_use;  // none in files from before it was recorded
  double wall_seconds = 0;
};

nlohmann::json RepertoireRecordJson(const RepertoireRecord& record);
// Throws InputError naming `source` when it is not a repertoire.json (no "methods", a field of
// the wrong type).
RepertoireRecord ParseRepertoireRecord(const std::string& text, const std::string& source);

}  // namespace hexgait
