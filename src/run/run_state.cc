#include "run/run_state.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/output.h"

namespace hexgait {
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
  RefuseUnfinishedRun(folder, flag, "evolve");
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
