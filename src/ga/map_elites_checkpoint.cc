#include "ga/map_elites_checkpoint.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "hexgait repertoire archive";

// The parameters every archive has; the rest of "params" are the algorithm's own settings.
const std::vector<std::string> kSharedParams = {"seed",
                                                "evaluations",
                                                "batch",
                                                "descriptor",
                                                "bins",
                                                "symmetric",
                                                "time",
                                                "dt",
                                                "integrator",
                                                "check_interval",
                                                "divergence_speed",
                                                "early_stop",
                                                "stop_at_fall",
                                                "rest_kinetic_energy",
                                                "precision",
                                                "confirm_in_double"};

json ParamsJson(const MapElitesParams& p) {
  json j = {{"seed", std::to_string(p.seed)},
            {"evaluations", p.evaluations},
            {"batch", p.batch},
            {"descriptor", p.descriptor},
            {"bins", p.bins},
            {"symmetric", p.symmetric}};
  j.update(ParamsToJson(p.settings));
  AddRunOptionsJson(j, p.run, p.precision);
  // Only when on, so archives of runs without it keep their bytes.
  if (p.confirm_in_double) j["confirm_in_double"] = true;
  return j;
}

MapElitesParams ReadParams(const JsonReader& r, const std::string& algorithm) {
  MapElitesParams p;
  p.algorithm = algorithm;
  // Any other member is a setting of the algorithm, checked against its table when the search
  // continues (search/archive_optimizer.h).
  for (const auto& [key, value] : r.value().items()) {
    if (std::find(kSharedParams.begin(), kSharedParams.end(), key) != kSharedParams.end()) continue;
    if (!value.is_number()) r.Fail("'" + key + "' must be a number");
    p.settings.Set(key, value.get<double>(), value.is_number_integer());
  }
  p.seed = ReadSeed(r);
  p.evaluations = ReadInteger64(r, "evaluations");
  p.batch = r.Integer("batch");
  p.descriptor = r.String("descriptor");
  p.bins = r.Integer("bins");
  p.symmetric = r.Bool("symmetric");
  ReadRunOptionsJson(r, &p.run, &p.precision);
  p.confirm_in_double = r.Has("confirm_in_double") && r.Bool("confirm_in_double");
  return p;
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::string GenesHex(const Genome& genome) {
  static const char kDigits[] = "0123456789abcdef";
  std::string text;
  for (int8_t gene : genome.genes()) text += kDigits[static_cast<unsigned>(gene) & 15u];
  return text;
}

std::string FormatArchive(const MapElitesState& state, uint64_t scene_fingerprint,
                          const std::string& creature, const std::string& damage) {
  json j;
  AddFormatHeader(j, kFormat, kArchiveVersion);
  j["scene_fingerprint"] = Hex(scene_fingerprint);
  if (!creature.empty()) j["creature"] = creature;
  if (!damage.empty()) j["damage"] = damage;
  // Only for another algorithm than MAP-Elites, so MAP-Elites' archives keep their bytes.
  if (state.params.algorithm != kOriginalArchiveAlgorithm) j["algorithm"] = state.params.algorithm;
  if (!state.algorithm_state.is_null()) j["algorithm_state"] = state.algorithm_state;
  j["params"] = ParamsJson(state.params);
  j["batches"] = state.batches;
  j["evaluations"] = state.evaluations;
  json history = json::array();
  for (const ArchiveStats& s : state.history) {
    history.push_back({{"evaluations", s.evaluations},
                       {"filled", s.filled},
                       {"qd_score", s.qd_score},
                       {"best", s.best},
                       {"seconds", s.seconds},
                       {"diverged", s.diverged}});
    if (state.params.confirm_in_double) {
      history.back()["confirmed"] = s.confirmed;
      history.back()["refuted"] = s.refuted;
    }
  }
  j["history"] = history;
  // Elites in the order their cells were first filled: the order parents are drawn from.
  json elites = json::array();
  for (int cell : state.archive.filled()) {
    const Elite& e = *state.archive.at(cell);
    elites.push_back({{"cell", cell},
                      {"genes", GenesHex(e.genome)},
                      {"fitness", Number(e.fitness)},
                      {"found_at", e.found_at},
                      {"result", ResultJson(e.result)}});
  }
  j["elites"] = elites;
  j["checksum"] = Checksum(j);
  return j.dump(1) + "\n";
}

MapElitesState ParseArchive(const std::string& text, const std::string& source,
                            const CreatureModel& model, const MotorProgram& program) {
  const json root = ParseJson(text, source, kMaxArchiveBytes);
  const JsonReader r(root, source, "");
  if (!root.is_object()) r.Fail("not a repertoire archive (expected a JSON object)");
  std::vector<std::string> keys = FormatHeaderKeys();
  keys.insert(keys.end(),
              {"scene_fingerprint", "creature", "damage", "algorithm", "algorithm_state", "params",
               "batches", "evaluations", "history", "elites", "checksum"});
  r.RequireOnlyKeys(keys);
  if (r.Has("creature")) r.String("creature");
  if (r.Has("damage")) r.String("damage");
  if (r.String("format") != kFormat) r.Fail("not a hexgait repertoire archive");
  if (const int version = ReadFormatVersion(r); version != kArchiveVersion) {
    r.Fail("archive version " + std::to_string(version) + " is not supported");
  }
  if (r.String("scene_fingerprint") != Hex(SceneFingerprint(model, program))) {
    r.Fail(
        "was made with a different creature or motor program (pass the same --creature, "
        "--damage and "
        "--motor as the run that wrote it)");
  }
  MapElitesState state;
  try {
    const std::string algorithm =
        r.Has("algorithm") ? r.String("algorithm") : kOriginalArchiveAlgorithm;
    state = StartMapElites(ReadParams(r.Child("params"), algorithm), model);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind(source, 0) == 0) throw;
    throw InputError(source + ": params: " + what);
  }
  if (r.Has("algorithm_state")) state.algorithm_state = root["algorithm_state"];
  const MapElitesParams& p = state.params;
  state.batches = r.Integer("batches");
  state.evaluations = ReadInteger64(r, "evaluations");
  if (state.batches < 0 || state.evaluations < 0 || state.evaluations > p.evaluations ||
      state.evaluations > static_cast<long long>(state.batches) * p.batch) {
    r.Fail("'batches' and 'evaluations' do not fit the parameters");
  }
  const JsonReader history = r.Child("history");
  if (static_cast<int>(history.ArraySize()) != state.batches) {
    history.Fail("must have one entry per completed batch");
  }
  for (size_t i = 0; i < history.ArraySize(); ++i) {
    const JsonReader h = history.At(i);
    h.RequireOnlyKeys({"evaluations", "filled", "qd_score", "best", "seconds", "diverged",
                       "confirmed", "refuted"});
    ArchiveStats s;
    s.evaluations = ReadInteger64(h, "evaluations");
    s.filled = h.Integer("filled");
    s.qd_score = h.Number("qd_score");
    s.best = h.Number("best");
    s.seconds = h.Number("seconds");
    // Absent from archives before divergence was counted: none was recorded then.
    s.diverged = h.Has("diverged") ? ReadInteger64(h, "diverged") : 0;
    if (s.diverged < 0 || s.diverged > s.evaluations) {
      h.Fail("'diverged' must be in [0, evaluations]");
    }
    s.confirmed = h.Has("confirmed") ? ReadInteger64(h, "confirmed") : 0;
    s.refuted = h.Has("refuted") ? ReadInteger64(h, "refuted") : 0;
    if (s.confirmed < 0 || s.confirmed > s.evaluations || s.refuted < 0 ||
        s.refuted > s.confirmed) {
      h.Fail("'confirmed' must be in [0, evaluations] and 'refuted' in [0, confirmed]");
    }
    state.history.push_back(s);
  }
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(p.descriptor);
  const auto layout = MakeGenomeLayout(model, program, p.symmetric);
  const JsonReader elites = r.Child("elites");
  for (size_t i = 0; i < elites.ArraySize(); ++i) {
    const JsonReader e = elites.At(i);
    e.RequireOnlyKeys({"cell", "genes", "fitness", "found_at", "result"});
    Elite elite{Genome(layout), ReadResult(e.Child("result")), ReadNumber(e, "fitness"),
                ReadInteger64(e, "found_at")};
    const std::string genes = e.String("genes");
    if (static_cast<int>(genes.size()) != layout->num_genes()) {
      e.Fail("'genes' must have " + std::to_string(layout->num_genes()) + " hex digits");
    }
    for (int g = 0; g < layout->num_genes(); ++g) {
      const int digit = HexDigit(genes[static_cast<size_t>(g)]);
      if (digit < 0) e.Fail("'genes' must be lower-case hex digits");
      elite.genome.set_gene(g, digit >= 8 ? digit - 16 : digit);
    }
    if (!IsStandingGait(elite.result)) e.Fail("is not a gait that stands the test");
    if (elite.fitness != Fitness(elite.result)) e.Fail("fitness does not match its result");
    if (elite.found_at < 1 || elite.found_at > state.evaluations) {
      e.Fail("'found_at' is not one of the run's evaluations");
    }
    double behaviour[kMaxLegs * 2];
    descriptor.measure(model, elite.result, behaviour);
    const int cell = e.Integer("cell");
    if (cell != state.archive.CellOf(behaviour)) {
      e.Fail("'cell' is not the cell of its result's behaviour");
    }
    if (state.archive.at(cell)) e.Fail("a second elite for cell " + std::to_string(cell));
    state.archive.Offer(cell, std::move(elite));
  }
  if (!state.history.empty() &&
      (state.history.back().evaluations != state.evaluations ||
       state.history.back().filled != static_cast<int>(state.archive.filled().size()))) {
    r.Fail("the last history entry does not match the archive");
  }
  // Last, so a damaged field gets its own message above; this catches every other edit.
  if (r.String("checksum") != Checksum(root)) {
    r.Fail(
        "checksum does not match the content (the file was edited or damaged); resume from an "
        "unedited archive or start a new run");
  }
  return state;
}

}  // namespace hexgait
