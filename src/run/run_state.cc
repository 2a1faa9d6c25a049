#include "run/run_state.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {
namespace {

constexpr const char* kRunning = "state: running\n";
constexpr const char* kComplete = "state: complete\n";

std::string MarkerPath(const std::string& folder, const std::string& command) {
  return (std::filesystem::path(folder) / (".hexgait-" + command)).string();
}

std::string Header(const std::string& command) {
  return "written by hexgait " + command + "; a new run may replace it\n";
}

}  // namespace

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
  if (!std::filesystem::is_regular_file(path, ec)) return;
  if (std::filesystem::file_size(path, ec) > 4096 || ec) return;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().find(kRunning) == std::string::npos) return;
  throw InputError(flag + " '" + folder + "': its last " + command +
                   " did not finish (interrupted, failed or still running), so its files may "
                   "come from different runs; finish it with 'hexgait " +
                   command + " --resume " + folder + "' or start it again");
}

void RequireFolder(const std::string& folder, const std::string& flag) {
  std::error_code ec;
  if (!std::filesystem::exists(folder, ec)) {
    throw InputError(flag + " '" + folder + "': no such folder");
  }
  if (!std::filesystem::is_directory(folder, ec)) {
    throw InputError(flag + " '" + folder + "': is a file, not a folder");
  }
}

std::string FinishedRunGenome(const std::string& folder, const std::string& flag) {
  RequireFolder(folder, flag);
  RefuseUnfinishedRun(folder, flag);
  const std::string path = folder + "/best.genome";
  // Anything else at that name (a folder, a FIFO) gets ReadTextFile's own message.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(flag + " '" + folder +
                     "': no best.genome there (make one with 'hexgait evolve --out DIR')");
  }
  return path;
}

}  // namespace hexgait
