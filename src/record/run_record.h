// run.json, the record of an evolve run: its settings, both programs' outcomes and the history,
// as one type with one pair of JSON functions. `evolve` writes it; `sweep`'s summary reads it.
// Files from older hexgait still read: without "algorithm" a run is the paper's GA.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ga/evolution.h"
#include "sim/step_loop.h"

namespace hexgait {

// What run.json keeps of a RunResult (as `simulate --json` prints it).
struct OutcomeRecord {
  double distance = 0;
  bool fell = false;
  std::optional<double> fall_time;  // when it fell
  std::optional<int> fall_cycle;    // when it fell
  bool diverged = false;
  bool stopped_early = false;
};
OutcomeRecord OutcomeOf(const RunResult& result);
nlohmann::json OutcomeJson(const OutcomeRecord& outcome);
// Throws nlohmann::json's exceptions; the record that holds it names its file.
OutcomeRecord ParseOutcome(const nlohmann::json& j);

// Files written before other optimizers name none: the paper's GA made them.
inline constexpr const char* kOriginalEvolveAlgorithm = "ga";

struct RunRecord {
  std::string hexgait_version = HEXGAIT_VERSION;
  std::string algorithm = kOriginalEvolveAlgorithm;  // an optimizer of search/optimizers.cc
  uint64_t seed = 0;
  int population = 0, generations = 0;
  // The optimizer's own parameters, by its table (the GA's rates and elites, CMA-ES's sigma),
  // written as members of the record beside the others.
  nlohmann::json settings = nlohmann::json::object();
  bool symmetric = false;
  int genes = 0, chromosome_bits = 0;  // chromosome_bits: a discrete genome's only
  int threads = 0, batch_lanes = 0;
  bool early_stop = false;
  double time = 0, dt = 0;
  std::string integrator, precision, creature, motor;
  std::string damage;  // the creature's --damage; "" intact (then not written)
  double cycle_period = 0;
  int evaluations = 0;
  double wall_seconds = 0, seconds_per_evaluation = 0;
  OutcomeRecord unoptimized, best;
  double best_fitness = 0;
  std::vector<GenerationStats> history;  // best, mean, worst, evaluations, seconds

  // best / unoptimized distance; none when the unoptimised program did not move forward.
  std::optional<double> ratio() const;
};

nlohmann::json RunRecordJson(const RunRecord& record);
// Throws InputError naming `source` when a field is missing or of the wrong type.
RunRecord ParseRunRecord(const std::string& text, const std::string& source);

}  // namespace hexgait
