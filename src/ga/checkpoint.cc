#include "ga/checkpoint.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "ga/checkpoint_json.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;

json IndividualJson(const Individual& ind) {
  json genes = json::array();
  for (int8_t g : ind.genome.genes()) genes.push_back(static_cast<int>(g));
  return {{"genes", genes}, {"fitness", Number(ind.fitness)}, {"result", ResultJson(ind.result)}};
}

Individual ReadIndividual(const JsonReader& r, const std::shared_ptr<const GenomeLayout>& layout) {
  r.RequireOnlyKeys({"genes", "fitness", "result"});
  const JsonReader genes = r.Child("genes");
  if (static_cast<int>(genes.ArraySize()) != layout->num_genes()) {
    genes.Fail("has " + std::to_string(genes.ArraySize()) + " genes; this creature's genome has " +
               std::to_string(layout->num_genes()));
  }
  Individual ind{Genome(layout), {}, 0};
  for (int i = 0; i < layout->num_genes(); ++i) {
    const int g = genes.At(static_cast<size_t>(i)).AsInteger();
    if (g < kGeneMin || g > kGeneMax) genes.At(static_cast<size_t>(i)).Fail("gene outside [-8, 7]");
    ind.genome.set_gene(i, g);
  }
  ind.fitness = ReadNumber(r, "fitness");
  ind.result = ReadResult(r.Child("result"));
  return ind;
}

// The parameters every generational search has; the rest of "params" are its optimizer's own.
const std::vector<std::string> kSharedParams = {
    "seed",       "population",     "generations",
    "symmetric",  "time",           "dt",
    "integrator", "check_interval", "divergence_speed",
    "early_stop", "stop_at_fall",   "rest_kinetic_energy",
    "precision",  "start"};

}  // namespace

json EvolutionParamsJson(const EvolutionParams& p) {
  json j = {{"seed", std::to_string(p.seed)},
            {"population", p.population},
            {"generations", p.generations},
            {"symmetric", p.symmetric}};
  j.update(ParamsToJson(p.settings));
  if (!p.start.empty()) {
    json start = json::array();
    for (int8_t g : p.start) start.push_back(static_cast<int>(g));
    j["start"] = start;
  }
  AddRunOptionsJson(j, p.run, p.precision);
  return j;
}

EvolutionParams ReadEvolutionParams(const JsonReader& r) {
  EvolutionParams p;
  // Any other member is a setting of the optimizer, checked against its table.
  p.settings = ParamValues();
  for (const auto& [key, value] : r.value().items()) {
    if (std::find(kSharedParams.begin(), kSharedParams.end(), key) != kSharedParams.end()) continue;
    if (!value.is_number()) r.Fail("'" + key + "' must be a number");
    p.settings.Set(key, value.get<double>(), value.is_number_integer());
  }
  if (r.Has("start")) {
    const JsonReader start = r.Child("start");
    for (size_t i = 0; i < start.ArraySize(); ++i) {
      const int g = start.At(i).AsInteger();
      if (g < kGeneMin || g > kGeneMax) start.At(i).Fail("gene outside [-8, 7]");
      p.start.push_back(static_cast<int8_t>(g));
    }
  }
  p.seed = ReadSeed(r);
  p.population = r.Integer("population");
  p.generations = r.Integer("generations");
  p.symmetric = r.Bool("symmetric");
  ReadRunOptionsJson(r, &p.run, &p.precision);
  return p;
}

namespace {

// The checks a checksum cannot make for a version 1 file, and that catch a consistent-looking
// edit early with a precise message: finite fitnesses equal to their results', a history that
// matches the population, evaluation counts that add up, a best that is the history's best.
void CheckConsistency(const EvolutionCheckpoint& c, const JsonReader& r) {
  const auto check_individual = [&](const Individual& ind, const std::string& where) {
    if (!std::isfinite(ind.fitness)) r.Fail(where + ": fitness is not a finite number");
    if (ind.fitness != Fitness(ind.result)) {
      r.Fail(where + ": fitness does not match its result's distance");
    }
  };
  for (size_t i = 0; i < c.population.size(); ++i) {
    check_individual(c.population[i], "population[" + std::to_string(i) + "]");
  }
  long long evaluations = 0;
  double best_ever = -INFINITY;
  for (size_t i = 0; i < c.so_far.history.size(); ++i) {
    const GenerationStats& g = c.so_far.history[i];
    const std::string where = "history[" + std::to_string(i) + "]";
    if (g.generation != static_cast<int>(i))
      r.Fail(where + ": generation must be " + std::to_string(i));
    if (!std::isfinite(g.best) || !std::isfinite(g.mean) || !std::isfinite(g.worst)) {
      r.Fail(where + ": fitness is not a finite number");
    }
    // Not mean within [worst, best]: the rounded mean of equal fitnesses can lie just outside.
    if (!(g.worst <= g.best)) r.Fail(where + ": worst is above best");
    if (g.best_index < 0 || g.best_index >= c.params.population || g.evaluations < 0 ||
        g.evaluations > c.params.population) {
      r.Fail(where + ": best_index or evaluations out of range");
    }
    evaluations += g.evaluations;
    best_ever = std::max(best_ever, g.best);
  }
  if (evaluations != c.so_far.total_evaluations) {
    r.Fail("'total_evaluations' is not the sum of the history's evaluations");
  }
  // The last generation's statistics are those of the population that is kept.
  const GenerationStats& last = c.so_far.history.back();
  double best = c.population[0].fitness, worst = best;
  for (const Individual& ind : c.population) {
    best = std::max(best, ind.fitness);
    worst = std::min(worst, ind.fitness);
  }
  if (last.best != best || last.worst != worst ||
      c.population[static_cast<size_t>(last.best_index)].fitness != best) {
    r.Fail("the last history entry does not match the population");
  }
  if (!c.so_far.best) r.Fail("'best' is missing");
  check_individual(*c.so_far.best, "best");
  if (c.so_far.best->fitness != best_ever) r.Fail("'best' is not the best in the history");
}

}  // namespace

json HistoryJson(const std::vector<GenerationStats>& history) {
  json out = json::array();
  for (const GenerationStats& g : history) {
    out.push_back({{"generation", g.generation},
                   {"best", Number(g.best)},
                   {"mean", Number(g.mean)},
                   {"worst", Number(g.worst)},
                   {"best_index", g.best_index},
                   {"evaluations", g.evaluations},
                   {"diverged", g.diverged},
                   {"seconds", g.seconds}});
  }
  return out;
}

std::vector<GenerationStats> ReadHistory(const JsonReader& history, int generations) {
  if (static_cast<int>(history.ArraySize()) != generations) {
    history.Fail("must have one entry per completed generation");
  }
  std::vector<GenerationStats> out;
  for (size_t i = 0; i < history.ArraySize(); ++i) {
    const JsonReader h = history.At(i);
    h.RequireOnlyKeys({"generation", "best", "mean", "worst", "best_index", "evaluations",
                       "diverged", "seconds"});
    GenerationStats g;
    g.generation = h.Integer("generation");
    g.best = ReadNumber(h, "best");
    g.mean = ReadNumber(h, "mean");
    g.worst = ReadNumber(h, "worst");
    g.best_index = h.Integer("best_index");
    g.evaluations = h.Integer("evaluations");
    // Absent from checkpoints before divergence was counted: none was recorded then.
    g.diverged = h.Has("diverged") ? h.Integer("diverged") : 0;
    if (g.diverged < 0 || g.diverged > g.evaluations)
      h.Fail("'diverged' must be in [0, evaluations]");
    g.seconds = h.Number("seconds");
    out.push_back(g);
  }
  return out;
}

uint64_t SceneFingerprint(const CreatureModel& model, const MotorProgram& program) {
  Fingerprint f;
  f.AddAll(model.mass);
  for (const Eigen::Vector3d& p : model.rest_position) {
    for (int k = 0; k < 3; ++k) f.Add(p[k]);
  }
  f.AddAll(model.spring_a);
  f.AddAll(model.spring_b);
  f.AddAll(model.stiffness);
  f.AddAll(model.damping);
  f.AddAll(model.rest_length);
  f.AddAll(model.motor_springs);
  // Only a damaged creature adds these (weak and short also change stiffness, damping and
  // rest_length above), so an intact creature's fingerprint is what it always was.
  if (!model.spring_locked.empty()) {
    f.AddAll(model.spring_locked);
    f.AddAll(model.motor_length_scale);
  }
  const PhysicsConstants& c = model.physics;
  for (double v : {c.gravity, c.ground_stiffness, c.ground_damping, c.friction, c.slip_velocity,
                   c.fall_height, c.fall_tilt_degrees}) {
    f.Add(v);
  }
  for (const Leg& leg : model.legs) {
    f.Add(leg.name);
    f.Add(static_cast<long long>(leg.foot));
    f.AddAll(leg.springs);
  }
  for (double v : {program.cycle_period, program.mirror_time_offset, program.gene_length_step,
                   program.transition_time}) {
    f.Add(v);
  }
  for (const LegPosition& p : program.positions) {
    f.Add(p.name);
    for (int k = 0; k < 3; ++k) f.Add(p.foot_offset[k]);
  }
  for (const Instruction& i : program.instructions) {
    f.Add(i.time);
    f.Add(static_cast<long long>(i.leg));
    f.Add(static_cast<long long>(i.position));
  }
  return f.value();
}

std::string FormatCheckpoint(const EvolutionCheckpoint& c, uint64_t scene_fingerprint,
                             const std::string& creature, const std::string& damage) {
  json j;
  AddFormatHeader(j, "hexgait evolve checkpoint", kCheckpointVersion);
  j["scene_fingerprint"] = Hex(scene_fingerprint);
  if (!creature.empty()) j["creature"] = creature;
  if (!damage.empty()) j["damage"] = damage;
  j["params"] = EvolutionParamsJson(c.params);
  j["generation"] = c.generation;
  j["total_evaluations"] = c.so_far.total_evaluations;
  j["history"] = HistoryJson(c.so_far.history);
  j["best"] = c.so_far.best ? IndividualJson(*c.so_far.best) : json(nullptr);
  json population = json::array();
  for (const Individual& ind : c.population) population.push_back(IndividualJson(ind));
  j["population"] = population;
  j["checksum"] = Checksum(j);
  return j.dump(1) + "\n";
}

std::string CheckpointSceneFingerprint(const std::string& text) {
  const json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!root.is_object()) return "";
  const auto it = root.find("scene_fingerprint");
  return it != root.end() && it->is_string() ? it->get<std::string>() : "";
}

std::string CheckpointCreature(const std::string& text) {
  const json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!root.is_object()) return "";
  const auto it = root.find("creature");
  return it != root.end() && it->is_string() ? it->get<std::string>() : "";
}

std::string CheckpointDamage(const std::string& text) {
  const json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!root.is_object()) return "";
  const auto it = root.find("damage");
  return it != root.end() && it->is_string() ? it->get<std::string>() : "";
}

EvolutionCheckpoint ParseCheckpoint(const std::string& text, const std::string& source,
                                    const CreatureModel& model, const MotorProgram& program,
                                    bool* unchecked) {
  const json root = ParseJson(text, source, kMaxCheckpointBytes);
  const JsonReader r(root, source, "");
  if (!root.is_object()) r.Fail("not a checkpoint (expected a JSON object)");
  std::vector<std::string> keys = FormatHeaderKeys();
  keys.insert(keys.end(), {"scene_fingerprint", "creature", "damage", "params", "generation",
                           "total_evaluations", "history", "best", "population", "checksum"});
  r.RequireOnlyKeys(keys);
  if (r.Has("creature")) r.String("creature");
  if (r.Has("damage")) r.String("damage");  // a name or path; the fingerprint decides
  if (r.String("format") != "hexgait evolve checkpoint") r.Fail("not a hexgait evolve checkpoint");
  const int version = ReadFormatVersion(r);
  if (version != kCheckpointVersion && version != 1) {
    r.Fail("checkpoint version " + std::to_string(version) + " is not supported");
  }
  // Version 1 had no checksum; from version 2 on it is required, so deleting it is no way
  // around it.
  if (version == 1 && r.Has("checksum")) r.Fail("a version 1 checkpoint has no 'checksum'");
  const std::string checksum = version == 1 ? std::string() : r.String("checksum");
  if (r.String("scene_fingerprint") != Hex(SceneFingerprint(model, program))) {
    r.Fail(
        "was made with a different creature or motor program (pass the same --creature, "
        "--damage and "
        "--motor as the interrupted run)");
  }
  EvolutionCheckpoint c;
  try {
    c.params = ReadEvolutionParams(r.Child("params"));
    ValidateEvolutionParams(c.params);
  } catch (const InputError& e) {
    throw InputError(source + ": params: " + e.what());
  }
  const auto layout = MakeGenomeLayout(model, program, c.params.symmetric);
  c.generation = r.Integer("generation");
  if (c.generation < 0 || c.generation > c.params.generations) {
    r.Fail("'generation' must be in [0, " + std::to_string(c.params.generations) + "]");
  }
  c.so_far.total_evaluations = r.Integer("total_evaluations");
  c.so_far.history = ReadHistory(r.Child("history"), c.generation + 1);
  if (!root.at("best").is_null()) c.so_far.best = ReadIndividual(r.Child("best"), layout);
  const JsonReader population = r.Child("population");
  if (static_cast<int>(population.ArraySize()) != c.params.population) {
    population.Fail("must have " + std::to_string(c.params.population) + " individuals");
  }
  for (size_t i = 0; i < population.ArraySize(); ++i) {
    c.population.push_back(ReadIndividual(population.At(i), layout));
  }
  CheckConsistency(c, r);
  // Last, so a damaged field gets its own message above; this catches every other edit (a
  // seed, a time or a rate changed mid-run).
  if (version != 1 && checksum != Checksum(root)) {
    r.Fail(
        "checksum does not match the content (the file was edited or damaged); resume "
        "from an unedited checkpoint or start a new run");
  }
  if (unchecked) *unchecked = version == 1;
  return c;
}

}  // namespace hexgait
