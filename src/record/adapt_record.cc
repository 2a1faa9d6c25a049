#include "record/adapt_record.h"

#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

// adapt.json is a few KB; a bigger file is not one.
constexpr size_t kMaxAdaptRecordBytes = size_t{1} << 20;

int Count(const JsonReader& r, const std::string& key, int at_least) {
  const int n = r.Integer(key);
  if (n < at_least) r.Fail("'" + key + "' must be at least " + std::to_string(at_least));
  return n;
}

}  // namespace

AdaptSummary ParseAdaptSummary(const std::string& text, const std::string& source) {
  const nlohmann::json root = ParseJson(text, source, kMaxAdaptRecordBytes);
  const JsonReader r(root, source, "");
  if (!root.is_object()) r.Fail("not an adapt.json hexgait wrote (expected a JSON object)");
  AdaptSummary a;
  a.repertoire = r.String("repertoire");
  a.has_scene = r.Has("scene");
  if (a.has_scene) {
    const JsonReader s = r.Child("scene");
    a.scene.creature = s.String("creature");
    a.scene.motor = s.String("motor");
    a.scene.dt = s.PositiveNumber("dt");
    a.scene.integrator = s.String("integrator");
    a.scene.fingerprint = s.String("scene_fingerprint");
  }
  a.damage = r.String("damage");
  a.time = r.PositiveNumber("time");
  a.elites = Count(r, "elites", 1);
  a.trials = Count(r, "trials", 1);
  const double stop = r.Child("params").Number("stop_fraction");
  if (!(stop > 0 && stop <= 1)) r.Child("params").Fail("'stop_fraction' must be in (0, 1]");
  a.stop_fraction = stop;
  a.adapted = r.Child("adapted").Number("distance");
  a.intact_best = r.Child("intact_best").Number("damaged_distance");
  a.best_elite = r.Child("best_elite_on_damaged").Number("distance");
  a.random_best = r.Child("random_elites").Number("best");
  a.ga_best = r.Child("ga_from_intact_best").Number("best");
  a.ga_evaluations = Count(r.Child("ga_from_intact_best"), "evaluations", 0);
  return a;
}

}  // namespace hexgait
