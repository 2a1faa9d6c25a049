// endurance.json, the record of a `hexgait endurance` study: its settings, the conditions the
// gaits ran under and each gait's test run, as one type with one pair of JSON functions.
// `endurance` writes it. Files from older hexgait still read: a key it lacks keeps its default.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "record/run_record.h"

namespace hexgait {

// One condition of the study (study/endurance.h's EnduranceCondition, as written).
struct EnduranceConditionRecord {
  std::string name;   // none, push, slope-up, ...
  std::string label;  // "push sideways, impulse 2, random phase"
  double horizon = 0;
  int trials = 1;
};

// One gait and its run of the test it was evolved for.
struct EnduranceGaitRecord {
  std::string group, name;
  OutcomeRecord test;
};

struct EnduranceRecord {
  std::string hexgait_version = HEXGAIT_VERSION;
  double test_time = 0, dt = 0;
  std::string integrator;
  std::string damage;  // the creature's --damage; "" intact (then not written)
  double long_factor = 0, perturbed_factor = 0, push_impulse = 0, slope_degrees = 0, jitter = 0;
  int trials = 0;
  double step_factor = 0;
  uint64_t seed = 0;
  int random_wanted = 0, random_tried = 0;
  std::vector<EnduranceConditionRecord> conditions;  // "none" first
  std::vector<EnduranceGaitRecord> gaits;
  double wall_seconds = 0;
};

nlohmann::json EnduranceRecordJson(const EnduranceRecord& record);
// Throws InputError naming `source` when it is not an endurance.json (a field of the wrong type,
// a gait without its test run).
EnduranceRecord ParseEnduranceRecord(const std::string& text, const std::string& source);

}  // namespace hexgait
