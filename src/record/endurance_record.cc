#include "record/endurance_record.h"

#include <limits>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;

// A line per gait and per condition: far below this.
constexpr size_t kMaxEnduranceRecordBytes = size_t{64} << 20;

}  // namespace

json EnduranceRecordJson(const EnduranceRecord& r) {
  json info;
  info["command"] = "hexgait endurance";
  info["hexgait_version"] = r.hexgait_version;
  info["test_time"] = r.test_time;
  info["dt"] = r.dt;
  info["integrator"] = r.integrator;
  if (!r.damage.empty()) info["damage"] = r.damage;
  info["long_factor"] = r.long_factor;
  info["perturbed_factor"] = r.perturbed_factor;
  info["push_impulse"] = r.push_impulse;
  info["slope_degrees"] = r.slope_degrees;
  info["jitter"] = r.jitter;
  info["trials"] = r.trials;
  info["step_factor"] = r.step_factor;
  info["seed"] = r.seed;
  info["random_wanted"] = r.random_wanted;
  info["random_tried"] = r.random_tried;
  for (const EnduranceConditionRecord& c : r.conditions) {
    info["conditions"].push_back(
        {{"name", c.name}, {"label", c.label}, {"horizon", c.horizon}, {"trials", c.trials}});
  }
  for (const EnduranceGaitRecord& g : r.gaits) {
    info["gaits"].push_back({{"group", g.group}, {"name", g.name}, {"test", OutcomeJson(g.test)}});
  }
  info["wall_seconds"] = r.wall_seconds;
  return info;
}

EnduranceRecord ParseEnduranceRecord(const std::string& text, const std::string& source) {
  try {
    const json j = ParseJson(text, source, kMaxEnduranceRecordBytes);
    EnduranceRecord r;
    r.hexgait_version = j.value("hexgait_version", "");
    r.test_time = j.value("test_time", 0.0);
    r.dt = j.value("dt", 0.0);
    r.integrator = j.value("integrator", "");
    r.damage = j.value("damage", "");
    r.long_factor = j.value("long_factor", 0.0);
    r.perturbed_factor = j.value("perturbed_factor", 0.0);
    r.push_impulse = j.value("push_impulse", 0.0);
    r.slope_degrees = j.value("slope_degrees", 0.0);
    r.jitter = j.value("jitter", 0.0);
    r.trials = IntOr(j, "trials", 0, 0, std::numeric_limits<int>::max());
    r.step_factor = j.value("step_factor", 0.0);
    r.seed = SeedValue(j.value("seed", json(0)));  // value(key, uint64_t) casts 1e30 unchecked
    r.random_wanted = IntOr(j, "random_wanted", 0, 0, std::numeric_limits<int>::max());
    r.random_tried = IntOr(j, "random_tried", 0, 0, std::numeric_limits<int>::max());
    if (j.contains("conditions")) {
      for (const json& c : j.at("conditions")) {
        r.conditions.push_back({c.at("name").get<std::string>(), c.value("label", ""),
                                c.at("horizon").get<double>(),
                                IntOr(c, "trials", 1, 0, std::numeric_limits<int>::max())});
      }
    }
    if (j.contains("gaits")) {
      for (const json& g : j.at("gaits")) {
        r.gaits.push_back(
            {g.value("group", ""), g.at("name").get<std::string>(), ParseOutcome(g.at("test"))});
      }
    }
    r.wall_seconds = j.value("wall_seconds", 0.0);
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": not an endurance.json written by hexgait endurance (" + e.what() +
                     ")");
  }
}

}  // namespace hexgait
