#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/folder_path.h"
#include "util/output.h"

namespace hexgait {
namespace fs = std::filesystem;
namespace {

constexpr const char* kRunning = "state: running\n";
constexpr const char* kComplete = "state: complete\n";

std::string MarkerName(const std::string& command) {
  return ".hexgait-" + command;
}

std::string MarkerPath(const std::string& folder, const std::string& command) {
  return (fs::path(folder) / MarkerName(command)).string();
}

std::string Header(const std::string& command) {
  return "written by hexgait " + command + "; a new run may replace it\n";
}

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

ResumableFolder::ResumableFolder(const std::string& given, const std::string& flag,
                                 const std::string& command, const std::vector<std::string>& files,
                                 const std::vector<std::string>& legacy_files)
    : path_(NormalFolderPath(given)), command_(command) {
  const std::string& path = path_;  // one spelling for every check and write
  const std::string marker = MarkerName(command);
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
  MarkRunStarted(path, command);
}

void ResumableFolder::Write(const std::string& name, const std::string& text) const {
  WriteFileAtomically(File(name), text);
}

void ResumableFolder::Complete() const {
  MarkRunComplete(path_, command_);
}

void MarkRunStarted(const std::string& folder, const std::string& command) {
  WriteFileAtomically(MarkerPath(folder, command), Header(command) + kRunning);
}

void MarkRunComplete(const std::string& folder, const std::string& command) {
  WriteFileAtomically(MarkerPath(folder, command), Header(command) + kComplete);
}

void RefuseUnfinishedRun(const std::string& folder, const std::string& flag,
                         const std::string& command) {
  const std::string path = MarkerPath(folder, command);
  std::error_code ec;
  // Only a small regular file is read: the marker is never a FIFO a reader could block on.
  if (!fs::is_regular_file(path, ec)) return;
  if (fs::file_size(path, ec) > 4096 || ec) return;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().find(kRunning) == std::string::npos) return;
  throw InputError(flag + " '" + folder + "': its last " + command +
                   " did not finish (interrupted, failed or still running), so its files may "
                   "come from different runs; finish it with 'hexgait " +
                   command + " --resume " + folder + "' or start it again");
}

}  // namespace hexgait
