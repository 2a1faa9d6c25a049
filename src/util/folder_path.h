// One spelling of an output folder, taken once before any check or write: `out/figs/.`,
// `out/figs/` and `out/./figs` all name `out/figs`, so the folder checked before the work is
// the folder renamed into place after it. A name that ends in `.` or `..` becomes absolute: a
// folder replaced whole needs a name of its own to build beside (`out/figs.partial.XXXXXX`).
#pragma once

#include <filesystem>
#include <string>

namespace hexgait {

inline std::string NormalFolderPath(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return path;
  fs::path normal = fs::path(path).lexically_normal();
  std::string text = normal.string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  const std::string name = fs::path(text).filename().string();
  if (name == "." || name == "..") {
    std::error_code ec;
    const fs::path absolute = fs::absolute(text, ec);
    if (!ec) {
      text = absolute.lexically_normal().string();
      while (text.size() > 1 && text.back() == '/') text.pop_back();
    }
  }
  return text;
}

}  // namespace hexgait
