#include "run/run_folder.h"

#include <filesystem>

#include "ga/checkpoint.h"
#include "motor/assets.h"
#include "run/run_state.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/folder_path.h"
#include "util/json_file.h"

namespace hexgait {
namespace fs = std::filesystem;
namespace {

// Whether some hexgait command marked the folder as its own (a .hexgait-COMMAND file).
bool HasAnyMarker(const std::string& path) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(path, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".hexgait-", 0) == 0 && name != kLockFileName) return true;
  }
  return false;
}

}  // namespace

RunFolder::RunFolder(const std::string& given, const std::string& flag, const std::string& command,
                     const std::vector<std::string>& files,
                     const std::vector<std::string>& legacy_files)
    : path_(NormalFolderPath(given)), command_(command) {
  const std::string& path = path_;  // one spelling for every check and write
  const std::string marker = ".hexgait-" + command;
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) {
      throw InputError(flag + " '" + path + "': is a file, expected a folder");
    }
    bool ours = fs::is_empty(path, ec) || fs::exists(fs::path(path) / marker, ec);
    // A run from before markers is recognised by its files, but only in a folder that no
    // hexgait command has marked as its own: a report folder holds a run.json too.
    if (!ours && !HasAnyMarker(path)) {
      for (const std::string& name : legacy_files)
        ours = ours || fs::exists(fs::path(path) / name, ec);
    }
    if (!ours) {
      throw InputError(flag + " '" + path + "': folder exists and was not written by hexgait " +
                       command + " (no " + marker + "); choose a new or empty folder");
    }
  }
  fs::create_directories(path, ec);
  if (ec || !fs::is_directory(path)) {
    throw InputError(flag + " '" + path + "': cannot create folder" +
                     (ec ? ": " + ec.message() : ""));
  }
  for (const std::string& name : files) CheckOutputPath(File(name), flag);
  // Held until the run ends: a second run into this folder is refused, naming this one.
  lock_ = std::make_unique<FolderLock>(path, flag);
  // Until the last result is written, readers of this folder refuse it: an older run's results
  // may still lie beside this run's state.
  MarkRunStarted(path, command);
}

void RunFolder::Write(const std::string& name, const std::string& text) const {
  WriteFileAtomically(File(name), text);
}

void RunFolder::Complete() const {
  MarkRunComplete(path_, command_);
}

std::string ResumeStatePath(const std::string& dir, const std::string& state_file,
                            const std::vector<std::string>& run_flags_given) {
  if (!run_flags_given.empty()) {
    throw InputError(run_flags_given.front() +
                     " cannot be combined with --resume: a resumed run keeps the parameters in "
                     "its " +
                     state_file);
  }
  const std::string path = dir + "/" + state_file;
  if (!fs::is_regular_file(path)) {
    throw InputError("--resume '" + dir + "': no " + state_file + " there");
  }
  return path;
}

std::string RecordedBuiltInCreature(const std::string& state_path, size_t max_bytes) {
  std::error_code ec;
  if (!fs::is_regular_file(state_path, ec)) return "";
  const std::string recorded = CheckpointCreature(ReadTextFile(state_path, max_bytes));
  return IsBuiltInCreature(recorded) ? recorded : "";
}

std::string RecordedDamage(const std::string& state_path, size_t max_bytes) {
  std::error_code ec;
  if (!fs::is_regular_file(state_path, ec)) return "";
  return CheckpointDamage(ReadTextFile(state_path, max_bytes));
}

}  // namespace hexgait
