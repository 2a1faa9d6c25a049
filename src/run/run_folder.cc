#include "run/run_folder.h"

#include <filesystem>

#include "ga/checkpoint.h"
#include "motor/assets.h"
#include "run/run_state.h"
#include "util/error.h"
#include "util/folder_path.h"
#include "util/json_file.h"
#include "util/output.h"

namespace hexgait {
namespace fs = std::filesystem;
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
