#include <filesystem>

#include "util/error.h"
#include "util/output.h"
#include "util/temp_registry.h"

namespace hexgait {

OutputFolder::OutputFolder(const std::string& folder, const char* first_file) : folder_(folder) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(folder, ec);
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    throw InputError("--out '" + folder + "': cannot create folder" +
                     (ec ? ": " + ec.message() : ""));
  }
  if (!existed) temp_handle_ = RegisterTemp(folder);
  path_ = folder + "/";
  CheckOutputPath(path_ + first_file, "--out");
}

OutputFolder::~OutputFolder() {
  if (temp_handle_ == 0) return;
  std::error_code ec;
  std::filesystem::remove(folder_, ec);  // only if empty: results are written atomically
  UnregisterTemp(temp_handle_);
}

void OutputFolder::Keep() {
  if (temp_handle_ != 0) UnregisterTemp(temp_handle_);
  temp_handle_ = 0;
}

}  // namespace hexgait
