#include "record/run_record.h"

#include <limits>
#include <set>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;

// run.json is at most a few hundred KB (a line of history per generation).
constexpr size_t kMaxRunRecordBytes = size_t{64} << 20;

}  // namespace

OutcomeRecord ParseOutcome(const json& j) {
  OutcomeRecord o;
  o.distance = j.at("distance").get<double>();
  o.fell = j.at("fell").get<bool>();
  if (!j.at("fall_time").is_null()) o.fall_time = j.at("fall_time").get<double>();
  if (!j.at("fall_cycle").is_null())
    o.fall_cycle = IntIn(j.at("fall_cycle"), 0, std::numeric_limits<int>::max());
  o.diverged = j.at("diverged").get<bool>();
  o.stopped_early = j.value("stopped_early", false);  // not in files before early stops
  return o;
}

OutcomeRecord OutcomeOf(const RunResult& r) {
  OutcomeRecord o;
  o.distance = r.distance;
  o.fell = r.fell;
  if (r.fell) {
    o.fall_time = r.fall_time;
    o.fall_cycle = r.fall_cycle;
  }
  o.diverged = r.diverged;
  o.stopped_early = r.stopped_early;
  return o;
}

json OutcomeJson(const OutcomeRecord& o) {
  json j;
  j["distance"] = o.distance;
  j["fell"] = o.fell;
  j["fall_time"] = o.fall_time ? json(*o.fall_time) : json(nullptr);
  j["fall_cycle"] = o.fall_cycle ? json(*o.fall_cycle) : json(nullptr);
  j["diverged"] = o.diverged;
  j["stopped_early"] = o.stopped_early;
  return j;
}

std::optional<double> RunRecord::ratio() const {
  if (!(unoptimized.distance > 0)) return std::nullopt;
  return best_fitness / unoptimized.distance;
}

// The members of run.json that are not an optimizer's settings.
const std::set<std::string> kRecordKeys = {"hexgait_version",
                                           "command",
                                           "algorithm",
                                           "seed",
                                           "population",
                                           "generations",
                                           "chromosome_bits",
                                           "symmetric",
                                           "genes",
                                           "threads",
                                           "batch_lanes",
                                           "early_stop",
                                           "time",
                                           "dt",
                                           "integrator",
                                           "precision",
                                           "creature",
                                           "damage",
                                           "motor",
                                           "cycle_period",
                                           "evaluations",
                                           "wall_seconds",
                                           "seconds_per_evaluation",
                                           "unoptimized",
                                           "best",
                                           "ratio_best_to_unoptimized",
                                           "history"};

json RunRecordJson(const RunRecord& r) {
  json run;
  run["hexgait_version"] = r.hexgait_version;
  run["command"] = "evolve";
  // Only for another optimizer than the GA, so the GA's records keep their bytes.
  if (r.algorithm != kOriginalEvolveAlgorithm) run["algorithm"] = r.algorithm;
  run["seed"] = r.seed;
  run["population"] = r.population;
  run["generations"] = r.generations;
  run.update(r.settings);
  if (r.chromosome_bits > 0) run["chromosome_bits"] = r.chromosome_bits;
  run["symmetric"] = r.symmetric;
  run["genes"] = r.genes;
  run["threads"] = r.threads;
  run["batch_lanes"] = r.batch_lanes;
  run["early_stop"] = r.early_stop;
  run["time"] = r.time;
  run["dt"] = r.dt;
  run["integrator"] = r.integrator;
  run["precision"] = r.precision;
  run["creature"] = r.creature;
  if (!r.damage.empty()) run["damage"] = r.damage;
  run["motor"] = r.motor;
  run["cycle_period"] = r.cycle_period;
  run["evaluations"] = r.evaluations;
  run["wall_seconds"] = r.wall_seconds;
  run["seconds_per_evaluation"] = r.seconds_per_evaluation;
  run["unoptimized"] = OutcomeJson(r.unoptimized);
  run["best"] = OutcomeJson(r.best);
  run["best"]["fitness"] = r.best_fitness;
  const std::optional<double> ratio = r.ratio();
  run["ratio_best_to_unoptimized"] = ratio ? json(*ratio) : json(nullptr);
  json history = json::array();
  for (const GenerationStats& g : r.history) {
    history.push_back({{"generation", g.generation},
                       {"best", g.best},
                       {"mean", g.mean},
                       {"worst", g.worst},
                       {"evaluations", g.evaluations},
                       {"diverged", g.diverged},
                       {"seconds", g.seconds}});
  }
  run["history"] = history;
  return run;
}

RunRecord ParseRunRecord(const std::string& text, const std::string& source) {
  try {
    const json run = ParseJson(text, source, kMaxRunRecordBytes);
    RunRecord r;
    r.hexgait_version = run.value("hexgait_version", "");
    r.algorithm = run.value("algorithm", kOriginalEvolveAlgorithm);
    r.seed = UnsignedInteger(run.at("seed"));
    r.population = IntIn(run.at("population"), 0, std::numeric_limits<int>::max());
    r.generations = IntIn(run.at("generations"), 0, std::numeric_limits<int>::max());
    // Every other number at the top is a setting of the optimizer.
    for (const auto& [key, value] : run.items()) {
      if (kRecordKeys.count(key)) continue;
      if (!value.is_number()) {
        throw InputError(source + ": '" + key + "' must be a number (a setting of the optimizer)");
      }
      r.settings[key] = value;
    }
    r.chromosome_bits = IntOr(run, "chromosome_bits", 0, 0, std::numeric_limits<int>::max());
    r.symmetric = run.at("symmetric").get<bool>();
    r.genes = IntOr(run, "genes", 0, 0, std::numeric_limits<int>::max());
    r.threads = IntOr(run, "threads", 0, 0, std::numeric_limits<int>::max());
    r.batch_lanes = IntOr(run, "batch_lanes", 0, 0, std::numeric_limits<int>::max());
    r.early_stop = run.value("early_stop", false);
    r.time = run.at("time").get<double>();
    r.dt = run.at("dt").get<double>();
    r.integrator = run.at("integrator").get<std::string>();
    r.precision = run.value("precision", "double");
    r.creature = run.value("creature", "");
    r.damage = run.value("damage", "");
    r.motor = run.value("motor", "");
    r.cycle_period = run.value("cycle_period", 0.0);
    r.evaluations = IntIn(run.at("evaluations"), 0, std::numeric_limits<int>::max());
    r.wall_seconds = run.value("wall_seconds", 0.0);
    r.seconds_per_evaluation = run.value("seconds_per_evaluation", 0.0);
    r.unoptimized = ParseOutcome(run.at("unoptimized"));
    r.best = ParseOutcome(run.at("best"));
    r.best_fitness = run.at("best").at("fitness").get<double>();
    for (const json& h : run.at("history")) {
      GenerationStats g;
      g.generation = IntIn(h.at("generation"), 0, std::numeric_limits<int>::max());
      g.best = h.at("best").get<double>();
      g.mean = h.at("mean").get<double>();
      g.worst = h.at("worst").get<double>();
      g.evaluations = IntIn(h.at("evaluations"), 0, std::numeric_limits<int>::max());
      g.diverged = IntOr(h, "diverged", 0, 0,
                         std::numeric_limits<int>::max());  // absent before divergence was counted
      g.seconds = h.at("seconds").get<double>();
      r.history.push_back(g);
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": not a run.json written by hexgait evolve (" + e.what() + ")");
  }
}

}  // namespace hexgait
