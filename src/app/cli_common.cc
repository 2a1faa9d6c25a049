#include "app/cli_common.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "eval/mpi_evaluator.h"
#include "ga/genome_io.h"
#include "model/damage.h"
#include "motor/assets.h"
#include "run/work_size.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {

void AddExpectOption(CLI::App* command, std::string& expect) {
  command->add_option("--expect", expect,
                      "Compare the file written with this approved one (as 'hexgait compare' "
                      "does); exit 1 and write OUT_STEM.diff.png beside it when they differ");
}

void ReportExpected(const std::optional<CompareResult>& expected) {
  if (!expected) return;
  std::printf("--expect: %s\n", expected->summary.c_str());
  if (!expected->diff_path.empty()) std::printf("wrote %s\n", expected->diff_path.c_str());
  if (!expected->match) throw ExitWith{1};
}

namespace {
void AddAllowLongFlag(CLI::App* command, bool& allow_long) {
  command->add_flag("--allow-long", allow_long,
                    "Run even if the estimated time is over an hour (or a movie has more than " +
                        std::to_string(kMaxMovieFrames) + " frames)");
}
}  // namespace

void AddSceneOptions(CLI::App* command, SceneOptions& options, bool with_allow_long) {
  // Each flag records that it was given: a folder's consumer refuses one that contradicts the
  // folder's record, and takes the record's value for the rest (run/folder_scene.h).
  const auto noted = [&options](CLI::Option* option) {
    const std::string name = option->get_name();
    option->each([&options, name](const std::string&) { options.given.insert(name); });
    return option;
  };
  noted(command->add_option("--creature", options.creature_path,
                            "Creature: a built-in name (" + BuiltInCreatureList() + "; default " +
                                kDefaultCreature + ") or a creature file (JSON)"));
  noted(command->add_option("--motor", options.motor_path,
                            "Motor program (JSON); default: the creature's built-in program "
                            "(assets/metachronal.json for hexapod and creature files, "
                            "assets/wedge_metachronal.json for wedge)"));
  noted(command->add_option("--damage", options.damage,
                            std::string("Damage the creature: ") + kDamageHelp));
  noted(command->add_option("--dt", options.dt, "Integration time step (time units)"))
      ->capture_default_str();
  noted(command->add_option("--integrator", options.integrator,
                            "Integrator: euler (the paper's), symplectic-euler, verlet, rk4, "
                            "implicit-euler"))
      ->capture_default_str();
  if (with_allow_long) AddAllowLongFlag(command, options.allow_long);
}

void AddGenomeOptions(CLI::App* command, GenomeChoice& choice) {
  auto* genome = command->add_option("--genome", choice.path,
                                     "Genome file to run (from 'hexgait evolve': DIR/best.genome)");
  auto* unopt = command->add_flag("--unoptimized", choice.unoptimized,
                                  "Run the unoptimised motor program (all genes 0; the default)");
  genome->excludes(unopt);
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

}  // namespace hexgait
