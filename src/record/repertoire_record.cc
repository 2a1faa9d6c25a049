#include "record/repertoire_record.h"

#include <limits>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;

// A few KB: a line per method and per showcased elite.
constexpr size_t kMaxRepertoireRecordBytes = size_t{16} << 20;

}  // namespace

json RepertoireRecordJson(const RepertoireRecord& r) {
  json info;
  info["command"] = "hexgait repertoire";
  info["hexgait_version"] = r.hexgait_version;
  info["seed"] = std::to_string(r.seed);
  info["algorithm"] = r.algorithm;
  info["settings"] = r.settings;
  info["descriptor"] = r.descriptor;
  info["axes"] = r.axes;
  info["bins"] = r.bins;
  info["cells"] = r.cells;
  info["threads"] = r.threads;
  info["ranks"] = r.ranks;
  info["time"] = r.time;
  info["dt"] = r.dt;
  info["precision"] = r.precision;
  for (const RepertoireMethodRecord& m : r.methods) {
    info["methods"].push_back({{"name", m.name},
                               {"evaluations", m.evaluations},
                               {"filled", m.filled},
                               {"qd_score", m.qd_score},
                               {"best_standing", m.best_standing},
                               {"best_fitness", m.best_fitness},
                               {"seconds", m.seconds},
                               {"diverged", m.diverged}});
  }
  for (const ShowcaseRecord& e : r.showcase) {
    info["showcase"].push_back({{"cell", e.cell},
                                {"genome", e.genome},
                                {"distance", e.distance},
                                {"duty_factors", e.duty_factors},
                                {"found_at", e.found_at}});
  }
  if (r.movie) {
    info["movie"] = {{"file", r.movie->file}, {"time", r.movie->time}, {"frames", r.movie->frames}};
  }
  if (r.machine_use) {
    const MachineUseRecord& u = *r.machine_use;
    info["machine_use"] = {
        {"seconds", u.seconds},
        {"cpu_seconds", u.cpu_seconds},
        {"lane_steps",
         {{"float", {{"stepped", u.float_lane_steps}, {"running", u.float_lane_steps_running}}},
          {"double",
           {{"stepped", u.double_lane_steps}, {"running", u.double_lane_steps_running}}}}}};
  }
  info["wall_seconds"] = r.wall_seconds;
  return info;
}

RepertoireRecord ParseRepertoireRecord(const std::string& text, const std::string& source) {
  try {
    const json j = ParseJson(text, source, kMaxRepertoireRecordBytes);
    RepertoireRecord r;
    r.hexgait_version = j.value("hexgait_version", "");
    r.seed = SeedValue(j.value("seed", json("0")));
    r.algorithm = j.value("algorithm", "");
    r.settings = j.value("settings", json::object());
    if (!r.settings.is_object()) throw InputError(source + ": 'settings' must be an object");
    r.descriptor = j.value("descriptor", "");
    r.axes = j.value("axes", std::vector<std::string>{});
    r.bins = IntOr(j, "bins", 0, 0, std::numeric_limits<int>::max());
    r.cells = IntegerOr(j, "cells", 0, 0, std::numeric_limits<long long>::max());
    r.threads = IntOr(j, "threads", 0, 0, std::numeric_limits<int>::max());
    r.ranks = IntOr(j, "ranks", 1, 0, std::numeric_limits<int>::max());
    r.time = j.value("time", 0.0);
    r.dt = j.value("dt", 0.0);
    r.precision = j.value("precision", "double");
    for (const json& m : j.at("methods")) {
      RepertoireMethodRecord method;
      method.name = m.at("name").get<std::string>();
      method.evaluations = IntegerIn(m.at("evaluations"), 0, std::numeric_limits<long long>::max());
      method.filled = IntegerIn(m.at("filled"), 0, std::numeric_limits<long long>::max());
      method.qd_score = m.at("qd_score").get<double>();
      method.best_standing = m.at("best_standing").get<double>();
      method.best_fitness = m.value("best_fitness", 0.0);
      method.seconds = m.value("seconds", 0.0);
      method.diverged =
          IntegerOr(m, "diverged", 0, 0,
                    std::numeric_limits<long long>::max());  // absent before divergence was counted
      r.methods.push_back(method);
    }
    if (j.contains("showcase")) {
      for (const json& e : j.at("showcase")) {
        ShowcaseRecord s;
        s.cell = IntIn(e.at("cell"), 0, std::numeric_limits<int>::max());
        s.genome = e.value("genome", "");
        s.distance = e.at("distance").get<double>();
        s.duty_factors = e.at("duty_factors").get<std::vector<double>>();
        s.found_at = IntegerOr(e, "found_at", 0, 0, std::numeric_limits<long long>::max());
        r.showcase.push_back(s);
      }
    }
    if (j.contains("movie")) {
      const json& m = j.at("movie");
      r.movie = RepertoireMovieRecord{
          m.value("file", "grid.mp4"), m.value("time", 0.0),
          IntegerOr(m, "frames", 0, 0, std::numeric_limits<long long>::max())};
    }
    if (j.contains("machine_use")) {
      const json& u = j.at("machine_use");
      const json& lanes = u.at("lane_steps");
      const auto count = [](const json& kind, const char* key) {
        return IntegerIn(kind.at(key), 0, std::numeric_limits<long long>::max());
      };
      r.machine_use = MachineUseRecord{
          u.at("seconds").get<double>(),        u.at("cpu_seconds").get<double>(),
          count(lanes.at("float"), "stepped"),  count(lanes.at("float"), "running"),
          count(lanes.at("double"), "stepped"), count(lanes.at("double"), "running")};
    }
    r.wall_seconds = j.value("wall_seconds", 0.0);
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": not a repertoire.json written by hexgait repertoire (" + e.what() +
                     ")");
  }
}

}  // namespace hexgait
