#include "run/folder_scene.h"

#include <charconv>
#include <filesystem>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "ga/map_elites_checkpoint.h"
#include "model/damage.h"
#include "motor/assets.h"
#include "record/adapt_record.h"
#include "record/run_record.h"
#include "run/run_state.h"
#include "sim/integrator.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

namespace fs = std::filesystem;

// run.json names the default program "built-in program of NAME" (record/run_record.h).
constexpr const char* kBuiltInProgram = "built-in program of ";

bool IsFile(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// 'value' (appended piecewise: GCC 12 warns falsely about "'" + value + "'").
std::string Quoted(const std::string& value) {
  std::string text = "'";
  text += value;
  text += '\'';
  return text;
}

RecordedScene FromRunRecord(const FolderArg& folder) {
  const std::string path = folder.dir + "/" + kRunRecordFile;
  const RunRecord record = ParseRunRecord(ReadTextFile(path), path);
  RecordedScene scene;
  scene.record = path;
  scene.options.creature_path = record.creature;
  scene.options.motor_path = record.motor.rfind(kBuiltInProgram, 0) == 0 ? "" : record.motor;
  scene.options.damage = record.damage;
  scene.options.dt = record.dt;
  scene.options.integrator = record.integrator;
  scene.precision = record.precision;
  // The run's checkpoint, kept beside its results, holds the fingerprint of its scene.
  const std::string checkpoint = folder.dir + "/" + kCheckpointFile;
  if (IsFile(checkpoint)) {
    scene.fingerprint = CheckpointSceneFingerprint(ReadTextFile(checkpoint, kMaxCheckpointBytes));
  }
  return scene;
}

RecordedScene FromArchive(const FolderArg& folder) {
  const std::string path = folder.dir + "/" + kArchiveFile;
  const nlohmann::json root =
      ParseJson(ReadTextFile(path, kMaxArchiveBytes), path, kMaxArchiveBytes);
  const JsonReader r(root, path, "");
  RecordedScene scene;
  scene.record = path;
  scene.options.creature_path = r.Has("creature") ? r.String("creature") : kDefaultCreature;
  scene.options.damage = r.Has("damage") ? r.String("damage") : "";
  RunOptions run;
  Precision precision = Precision::kDouble;
  ReadRunOptionsJson(r.Child("params"), &run, &precision);
  scene.options.dt = run.dt;
  scene.options.integrator = IntegratorName(run.integrator);
  scene.precision = PrecisionName(precision);
  scene.fingerprint = r.String("scene_fingerprint");
  return scene;
}

RecordedScene FromAdaptRecord(const FolderArg& folder) {
  const std::string path = folder.dir + "/" + kAdaptRecordFile;
  const AdaptSummary summary = ParseAdaptSummary(ReadTextFile(path), path);
  if (!summary.has_scene) {
    // Written before adapt.json kept its scene: the repertoire it names, if it is still there.
    if (!IsFile(summary.repertoire + "/" + kArchiveFile)) {
      throw InputError(path + " names no scene (an older hexgait wrote it) and its repertoire '" +
                       summary.repertoire + "' is gone: run 'hexgait adapt' again");
    }
    return FromArchive({folder.flag + "'s repertoire", summary.repertoire});
  }
  RecordedScene scene;
  scene.record = path;
  scene.options.creature_path = summary.scene.creature;
  scene.options.motor_path = summary.scene.motor;
  scene.options.dt = summary.scene.dt;
  scene.options.integrator = summary.scene.integrator;
  ParseIntegrator(scene.options.integrator);  // refuses a name it does not know
  scene.fingerprint = summary.scene.fingerprint;
  return scene;
}

// "FLAG 'DIR'": how a message names a folder.
std::string Named(const FolderArg& folder) {
  return folder.flag + " " + Quoted(folder.dir);
}

// The damage as DamageText writes it, whatever order or spelling the flag used.
std::string NormalisedDamage(const std::string& damage, const std::string& creature) {
  if (damage.empty()) return "";
  const CreatureModel model = LoadCreatureOrDefault(creature);
  return DamageText(ParseDamage(damage, model), model);
}

// Two spellings of one file (./a.json, a.json, a path through a symlink) are the same file.
bool SamePath(const std::string& a, const std::string& b) {
  if (a == b) return true;
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

// The shortest text that reads back as `v` (0.003, not 0.0030000000000000001).
std::string Shortest(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

std::string Shown(const std::string& value, const char* empty) {
  return value.empty() ? std::string(empty) : Quoted(value);
}

// Each scene flag the user gave must say what the record says.
void RefuseContradictions(const SceneOptions& flags, const RecordedScene& recorded,
                          const FolderArg& folder) {
  const SceneOptions& r = recorded.options;
  const auto refuse = [&](const std::string& flag, const std::string& given,
                          const std::string& was) {
    throw InputError(flag + " " + given + " contradicts " + Named(folder) + ", made with " + flag +
                     " " + was + " (" + recorded.record +
                     "); leave it out, or give --genome to run its genome on another scene");
  };
  const auto given = [&](const char* flag) { return flags.given.count(flag) > 0; };
  // A built-in creature by name; a file may have moved: its content's fingerprint decides.
  if (given("--creature") &&
      (IsBuiltInCreature(flags.creature_path) ||
       IsBuiltInCreature(CreatureLabel(r.creature_path))) &&
      CreatureLabel(flags.creature_path) != CreatureLabel(r.creature_path)) {
    refuse("--creature", Quoted(flags.creature_path), Quoted(CreatureLabel(r.creature_path)));
  }
  // Without a recorded fingerprint (older records), a file given must be the recorded one.
  if (recorded.fingerprint.empty()) {
    if (given("--creature") && !SamePath(flags.creature_path, CreatureLabel(r.creature_path))) {
      refuse("--creature", Quoted(flags.creature_path), Quoted(CreatureLabel(r.creature_path)));
    }
    if (given("--motor") && !SamePath(flags.motor_path, r.motor_path)) {
      refuse("--motor", Quoted(flags.motor_path), Shown(r.motor_path, "(the built-in program)"));
    }
  }
  if (given("--damage") && NormalisedDamage(flags.damage, r.creature_path) != r.damage) {
    refuse("--damage", Shown(flags.damage, "(none)"), Shown(r.damage, "none (intact)"));
  }
  if (given("--dt") && flags.dt != r.dt) {
    refuse("--dt", Shortest(flags.dt), Shortest(r.dt));
  }
  if (given("--integrator") && ParseIntegrator(flags.integrator) != ParseIntegrator(r.integrator)) {
    refuse("--integrator", flags.integrator, r.integrator);
  }
}

bool SameScene(const RecordedScene& a, const RecordedScene& b) {
  const SceneOptions &x = a.options, &y = b.options;
  const bool same_files =
      SamePath(CreatureLabel(x.creature_path), CreatureLabel(y.creature_path)) &&
      (x.motor_path.empty() ? y.motor_path.empty() : SamePath(x.motor_path, y.motor_path));
  const bool same_content = !a.fingerprint.empty() && !b.fingerprint.empty()
                                ? a.fingerprint == b.fingerprint
                                : same_files;
  return same_content && x.damage == y.damage && x.dt == y.dt &&
         ParseIntegrator(x.integrator) == ParseIntegrator(y.integrator);
}

}  // namespace

RecordedScene ReadRecordedScene(const FolderArg& folder) {
  RequireFolder(folder.dir, folder.flag);
  try {
    if (IsFile(folder.dir + "/" + kRunRecordFile)) return FromRunRecord(folder);
    if (IsFile(folder.dir + "/" + kArchiveFile)) return FromArchive(folder);
    if (IsFile(folder.dir + "/" + kAdaptRecordFile)) return FromAdaptRecord(folder);
  } catch (const InputError& e) {
    throw InputError(Named(folder) + ": " + e.what());
  }
  throw InputError(Named(folder) + ": no " + kRunRecordFile + ", " + kArchiveFile + " or " +
                   kAdaptRecordFile + " there, so nothing says which scene made it");
}

SceneOptions SceneOfFolders(const SceneOptions& flags, const std::vector<FolderArg>& folders) {
  if (folders.empty()) return flags;
  const RecordedScene first = ReadRecordedScene(folders.front());
  for (const FolderArg& folder : folders) {
    const RecordedScene recorded =
        folder.dir == folders.front().dir ? first : ReadRecordedScene(folder);
    if (!SameScene(recorded, first)) {
      throw InputError(Named(folder) + " was made on another scene than " + Named(folders.front()) +
                       " (creature, motor program, damage, --dt or --integrator): give folders of "
                       "one scene");
    }
    RefuseContradictions(flags, recorded, folder);
  }
  SceneOptions scene = first.options;
  // A creature or motor file given again (moved, say) is used; its fingerprint is checked.
  if (flags.given.count("--creature")) scene.creature_path = flags.creature_path;
  if (flags.given.count("--motor")) scene.motor_path = flags.motor_path;
  // A recorded file that is gone is named as the record's, not as a flag the user never gave.
  const auto refuse_missing = [&](const char* flag, const std::string& path) {
    if (flags.given.count(flag) || path.empty() || IsFile(path)) return;
    throw InputError(Named(folders.front()) + " was made with the file " + Quoted(path) + " (" +
                     flag + "), which is not there now: give it with " + flag);
  };
  if (!IsBuiltInCreature(CreatureLabel(scene.creature_path))) {
    refuse_missing("--creature", scene.creature_path);
  }
  refuse_missing("--motor", scene.motor_path);
  scene.allow_long = flags.allow_long;
  scene.expected_fingerprint = first.fingerprint;
  scene.expected_by = Named(folders.front()) + " (" + first.record + ")";
  return scene;
}

}  // namespace hexgait
