#include "app/cli_common.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "motor/assets.h"
#include "app/work_size.h"
#include "eval/mpi_evaluator.h"
#include "ga/genome_io.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {

void AddSceneOptions(CLI::App* command, SceneOptions& options, bool with_allow_long) {
  command->add_option("--creature", options.creature_path,
                      "Creature: a built-in name (" + BuiltInCreatureList() + "; default " +
                          kDefaultCreature + ") or a creature file (JSON)");
  command->add_option("--motor", options.motor_path,
                      "Motor program (JSON); default: the creature's built-in program "
                      "(assets/metachronal.json for hexapod and creature files, "
                      "assets/wedge_metachronal.json for wedge)");
  command->add_option("--dt", options.dt, "Integration time step (time units)")
      ->capture_default_str();
  command
      ->add_option("--integrator", options.integrator,
                   "Integrator: euler (the paper's), symplectic-euler, verlet, rk4, implicit-euler")
      ->capture_default_str();
  if (with_allow_long) AddAllowLongFlag(command, options.allow_long);
}

Scene LoadScene(const SceneOptions& options) {
  Scene scene{LoadCreatureOrDefault(options.creature_path), {}};
  scene.program = LoadMotorProgramOrDefault(options.motor_path, scene.model, options.creature_path);
  return scene;
}

RunOptions MakeRunOptions(const SceneOptions& options, double duration, int runs) {
  if (!std::isfinite(options.dt) || options.dt <= 0) {
    throw InputError("--dt must be a positive number of time units");
  }
  if (options.dt > 1.0) throw InputError("--dt must be at most 1 time unit");
  if (!std::isfinite(duration) || duration <= 0) {
    throw InputError("--time must be a positive number of time units");
  }
  // Above 2^53 steps a step number would no longer be exact as a double.
  if (duration / options.dt > 1e15) throw InputError("--time / --dt is more than 1e15 steps");
  RefuseLongRun(
      StepsText(duration, options.dt) + (runs > 1 ? ", " + std::to_string(runs) + " runs" : ""),
      duration / options.dt * runs * kSecondsPerStep, options.allow_long);
  RunOptions run;
  run.dt = options.dt;
  run.duration = duration;
  run.integrator = ParseIntegrator(options.integrator);
  run.check_interval = CheckIntervalFor(options.dt);
  return run;
}

void AddGenomeOptions(CLI::App* command, GenomeChoice& choice) {
  auto* genome = command->add_option("--genome", choice.path,
                                     "Genome file to run (from 'hexgait evolve': DIR/best.genome)");
  auto* unopt = command->add_flag("--unoptimized", choice.unoptimized,
                                  "Run the unoptimised motor program (all genes 0; the default)");
  genome->excludes(unopt);
}

Genome LoadGenomeChoice(const GenomeChoice& choice, const Scene& scene, std::string* label) {
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

nlohmann::json RunResultJson(const RunResult& r) {
  nlohmann::json j;
  j["distance"] = r.distance;
  j["fell"] = r.fell;
  j["fall_time"] = r.fell ? nlohmann::json(r.fall_time) : nlohmann::json(nullptr);
  j["fall_cycle"] = r.fell ? nlohmann::json(r.fall_cycle) : nlohmann::json(nullptr);
  j["diverged"] = r.diverged;
  j["stopped_early"] = r.stopped_early;
  return j;
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
  return j;
}

void PrintRunReport(const RunResult& result, const RunOptions& options, const std::string& label,
                    double cycle_period, std::FILE* out) {
  std::fprintf(out, "program    %s\n", label.c_str());
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

std::string CheckUnsigned64(const std::string& text) {
  if (text.find('-') != std::string::npos) return "must be a non-negative integer, got " + text;
  uint64_t value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec == std::errc::result_out_of_range) {
    return "must be at most 18446744073709551615 (2^64 - 1), got " + text;
  }
  return std::string();  // anything else is CLI11's to refuse, with its own message
}

CLI::Option* AddSeedOption(CLI::App* command, uint64_t& seed, const std::string& help) {
  return command->add_option("--seed", seed, help)->check(kNoSign)->capture_default_str();
}

CLI::Option* AddPrecisionOption(CLI::App* command, std::string& precision,
                                const std::string& help) {
  return command->add_option("--precision", precision, help)
      ->check(CLI::IsMember(kPrecisionNames))
      ->capture_default_str();
}

void CheckExtension(const std::string& path, const std::string& extension,
                    const std::string& flag) {
  std::string actual = std::filesystem::path(path).extension().string();
  for (char& c : actual) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (actual != extension) {
    throw InputError(flag + " '" + path + "': expected a name ending in " + extension +
                     ", the format this command writes");
  }
}

void RefuseEmptyValues(CLI::App& app) {
  static const CLI::Validator kNotEmpty(
      [](std::string& text) {
        return text.empty() ? std::string("empty value (give a path, name or number)")
                            : std::string();
      },
      "");
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    for (CLI::Option* option : command->get_options()) {
      if (option->get_type_size_max() > 0) option->check(kNotEmpty);
    }
    RefuseEmptyValues(*command);
  }
}

namespace {
std::set<const CLI::App*>& DistributedCommands() {
  static std::set<const CLI::App*> commands;
  return commands;
}
}  // namespace

void Distributed(CLI::App* command) {
  DistributedCommands().insert(command);
}

void LeaveMpiWorkersOut(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    if (!command->get_subcommands([](CLI::App*) { return true; }).empty()) {
      LeaveMpiWorkersOut(*command);
    } else if (!DistributedCommands().count(command)) {
      command->preparse_callback([](size_t) {
        if (MpiIsWorker()) throw MpiWorkerDone{};
      });
    }
  }
}

void ParseSize(const std::string& text, int* width, int* height) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto w = std::from_chars(begin, end, *width);
  const bool ok_w = w.ec == std::errc() && w.ptr != begin && w.ptr < end && *w.ptr == 'x';
  const auto h = ok_w ? std::from_chars(w.ptr + 1, end, *height) : w;
  if (!ok_w || h.ec != std::errc() || h.ptr != end || h.ptr == w.ptr + 1) {
    throw InputError("--size '" + text + "': expected WIDTHxHEIGHT, for example 1280x720");
  }
  if (*width < 16 || *height < 16 || *width > 7680 || *height > 4320) {
    throw InputError("--size '" + text + "': each side must be between 16 and 7680x4320");
  }
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
