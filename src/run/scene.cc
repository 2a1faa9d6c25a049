#include "run/scene.h"

#include <cmath>
#include <cstdio>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "ga/genome_io.h"
#include "model/damage.h"
#include "motor/assets.h"
#include "record/run_record.h"
#include "run/work_size.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output.h"

namespace hexgait {

CreatureModel LoadDamagedCreature(const std::string& creature_path, const std::string& damage) {
  CreatureModel model = LoadCreatureOrDefault(creature_path);
  ApplyDamage(ParseDamage(damage, model), &model);
  return model;
}

Scene LoadScene(const SceneOptions& options) {
  Scene scene{LoadDamagedCreature(options.creature_path, options.damage), {}};
  scene.program = LoadMotorProgramOrDefault(options.motor_path, scene.model, options.creature_path);
  if (!options.expected_fingerprint.empty() &&
      Hex(SceneFingerprint(scene.model, scene.program)) != options.expected_fingerprint) {
    throw InputError(options.expected_by +
                     " was made with a different creature or motor program than the one loaded "
                     "now: its scene fingerprint differs (a file was edited, or another given)");
  }
  return scene;
}

std::string SceneDamageText(const SceneOptions& options, const CreatureModel& model) {
  return DamageText(ParseDamage(options.damage, model), model);
}

void CheckStep(double dt) {
  if (!std::isfinite(dt) || dt <= 0) {
    throw InputError("--dt must be a positive number of time units");
  }
  if (dt > 1.0) throw InputError("--dt must be at most 1 time unit");
}

RunOptions MakeRunOptions(const SceneOptions& options, double duration, int runs,
                          const std::string& time_flag) {
  CheckStep(options.dt);
  if (!std::isfinite(duration) || duration <= 0) {
    throw InputError(time_flag + " must be a positive number of time units");
  }
  // A run shorter than one step would run no step at all and report a creature at rest.
  if (duration < options.dt) {
    char text[160];
    std::snprintf(text, sizeof text, "%s %g is shorter than one step (--dt %g)", time_flag.c_str(),
                  duration, options.dt);
    throw InputError(text);
  }
  // Above 2^53 steps a step number would no longer be exact as a double.
  if (duration / options.dt > 1e15) {
    throw InputError(time_flag + " / --dt is more than 1e15 steps");
  }
  // The creature's size counts (LoadScene loads it again: a few microseconds for the hexapod).
  RefuseLongRun(StepsText(duration, options.dt, time_flag) +
                    (runs > 1 ? ", " + std::to_string(runs) + " runs" : ""),
                EstimatedSimulationSeconds(LoadCreatureOrDefault(options.creature_path), runs,
                                           duration / options.dt, StepPath::kScalar),
                options.allow_long);
  RunOptions run;
  run.dt = options.dt;
  run.duration = duration;
  run.integrator = ParseIntegrator(options.integrator);
  run.check_interval = CheckIntervalFor(options.dt);
  return run;
}

Genome LoadGenomeChoice(const GenomeChoice& choice, const Scene& scene, std::string* label) {
  const int given =
      (choice.path.empty() ? 0 : 1) + (choice.genes.empty() ? 0 : 1) + (choice.unoptimized ? 1 : 0);
  if (given > 1) {
    throw InputError("--genome, genes and --unoptimized exclude each other: give one");
  }
  if (!choice.genes.empty()) {
    const auto full = MakeGenomeLayout(scene.model, scene.program, false);
    const auto symmetric = MakeGenomeLayout(scene.model, scene.program, true);
    const int n = static_cast<int>(choice.genes.size());
    if (n != full->num_genes() && n != symmetric->num_genes()) {
      throw InputError("genome: " + std::to_string(n) + " genes; this creature's program has " +
                       std::to_string(full->num_genes()) + " (or " +
                       std::to_string(symmetric->num_genes()) + " when symmetric)");
    }
    Genome genome(n == full->num_genes() ? full : symmetric);
    for (int g = 0; g < n; ++g) {
      const int gene = choice.genes[static_cast<size_t>(g)];
      if (gene < kGeneMin || gene > kGeneMax) {
        throw InputError("genome: gene " + std::to_string(g) + " is " + std::to_string(gene) +
                         ", outside [" + std::to_string(kGeneMin) + ", " +
                         std::to_string(kGeneMax) + "]");
      }
      genome.set_gene(g, gene);
    }
    if (label) *label = "genome";
    return genome;
  }
  if (choice.path.empty()) {
    if (label) *label = "unoptimized";
    return Genome(MakeGenomeLayout(scene.model, scene.program, false));
  }
  const std::string text = ReadTextFile(choice.path);
  const bool symmetric = GenomeFileIsSymmetric(text, choice.path);
  if (label) *label = "genome " + choice.path;
  return ParseGenome(text, choice.path, MakeGenomeLayout(scene.model, scene.program, symmetric));
}

IoPaths SceneInputs(const SceneOptions& scene, const GenomeChoice* genome) {
  IoPaths paths;
  if (!IsBuiltInCreature(scene.creature_path)) paths.Input("--creature", scene.creature_path);
  paths.Input("--motor", scene.motor_path);
  if (genome) paths.Input("--genome", genome->path);
  return paths;
}

SceneAndGenome LoadForOutput(const SceneOptions& scene, const GenomeChoice& genome,
                             const std::string& out, const std::string& extension,
                             const std::string& out_flag) {
  SceneInputs(scene, &genome).Output(out_flag, out).Check();
  if (!out.empty()) {
    CheckExtension(out, extension, out_flag);
    CheckOutputPath(out, out_flag);
  }
  Scene loaded = LoadScene(scene);
  std::string label;
  Genome chosen = LoadGenomeChoice(genome, loaded, &label);
  return {std::move(loaded), std::move(chosen), std::move(label)};
}

nlohmann::json RunResultJson(const RunResult& r) {
  return OutcomeJson(OutcomeOf(r));
}

nlohmann::json RunReportJson(const RunResult& result, const RunOptions& options,
                             const std::string& label, const CreatureModel& model,
                             double cycle_period) {
  nlohmann::json j = RunResultJson(result);
  j["program"] = label;
  j["steps"] = result.steps;
  j["time"] = result.end_time;
  j["dt"] = options.dt;
  j["integrator"] = IntegratorName(options.integrator);
  j["cycles"] = options.duration / cycle_period;
  j["min_body_height"] = result.min_body_height;
  j["max_tilt_degrees"] = result.max_tilt_degrees;
  j["mean_feet_on_ground"] = result.mean_feet_on_ground;
  // In the creature's leg order, as `legs` names them (a JSON object would sort them by name).
  nlohmann::json duty = nlohmann::json::array(), legs = nlohmann::json::array();
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    duty.push_back(result.DutyFactor(static_cast<int>(leg)));
    legs.push_back(model.legs[leg].name);
  }
  j["duty_factors"] = duty;
  j["legs"] = legs;
  if (!model.damage.empty()) j["damage"] = model.damage;
  return j;
}

void PrintRunReport(const RunResult& result, const RunOptions& options, const std::string& label,
                    const CreatureModel& model, double cycle_period, std::FILE* out) {
  std::fprintf(out, "program    %s\n", label.c_str());
  if (!model.damage.empty()) std::fprintf(out, "damage     %s\n", model.damage.c_str());
  std::fprintf(out, "distance   %.4f (body centre, along x)\n", result.distance);
  if (result.fell) {
    std::fprintf(out, "fell       at t = %.1f, in gait cycle %d\n", result.fall_time,
                 result.fall_cycle);
  } else {
    std::fprintf(out, "fell       did not fall\n");
  }
  std::fprintf(out, "simulated  %.1f time units = %.1f gait cycles, %lld steps of %g (%s)\n",
               result.end_time, result.end_time / cycle_period, result.steps, options.dt,
               IntegratorName(options.integrator).c_str());
}

std::string DivergenceMessage(const RunResult& result, const RunOptions& options,
                              double stable_dt) {
  char text[512];
  if (stable_dt > 0) {
    std::snprintf(text, sizeof text,
                  "the simulation diverged at t = %.4g (step %lld of dt %g, %s): %s; the largest "
                  "stable step found by halving dt is %g",
                  result.diverge_time, result.diverge_step, options.dt,
                  IntegratorName(options.integrator).c_str(), result.diverge_reason.c_str(),
                  stable_dt);
  } else {
    std::snprintf(text, sizeof text,
                  "the simulation diverged at t = %.4g (step %lld of dt %g, %s): %s; no stable "
                  "step found down to dt/%d (try --integrator implicit-euler)",
                  result.diverge_time, result.diverge_step, options.dt,
                  IntegratorName(options.integrator).c_str(), result.diverge_reason.c_str(),
                  1 << kStableStepHalvings);
  }
  return text;
}

}  // namespace hexgait
