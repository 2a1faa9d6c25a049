#include "run/io_paths.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/folder_path.h"

namespace hexgait {
namespace fs = std::filesystem;
namespace {

// The absolute path with links, "." and ".." resolved as far as it exists.
fs::path Resolved(const std::string& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : result;
}

// One file through links, relative paths and hard links: the same device and inode where both
// exist (std::filesystem::equivalent), the same resolved path otherwise.
bool SameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) {
    const bool same = fs::equivalent(a, b, ec);
    if (!ec) return same;
  }
  return Resolved(a) == Resolved(b);
}

// True if `path` is `folder` or lies somewhere inside it.
bool Inside(const std::string& path, const std::string& folder) {
  const fs::path p = Resolved(path), f = Resolved(folder);
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
    if (fi->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *fi) return false;
  }
  return true;
}

std::string Quoted(const std::string& flag, const std::string& path) {
  return flag + " '" + path + "'";
}

// Whether `text` is UTF-8 as the JSON writer checks it: every path is recorded in a JSON file.
bool IsUtf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

}  // namespace

IoPaths& IoPaths::Input(const std::string& flag, const std::string& path) {
  if (!path.empty()) inputs_.push_back({flag, path});
  return *this;
}

IoPaths& IoPaths::Output(const std::string& flag, const std::string& path) {
  outputs_.push_back({flag, path});
  return *this;
}

IoPaths& IoPaths::OutputFolder(const std::string& flag, const std::string& path) {
  output_folders_.push_back({flag, NormalFolderPath(path)});
  return *this;
}

void IoPaths::Check() const {
  for (const std::vector<Entry>* entries : {&inputs_, &outputs_, &output_folders_}) {
    for (const Entry& e : *entries) {
      if (!IsUtf8(e.path)) {
        // Printed without the path: the terminal could not show it either.
        throw InputError(e.flag +
                         ": the path is not UTF-8 text, which the records (JSON) that "
                         "name it need; rename it");
      }
    }
  }
  for (const Entry& out : outputs_) {
    for (const Entry& in : inputs_) {
      if (SameFile(out.path, in.path)) {
        throw InputError(Quoted(out.flag, out.path) + " is the same file as the input " +
                         Quoted(in.flag, in.path) + "; choose another output name");
      }
    }
  }
  for (const Entry& out : output_folders_) {
    for (const Entry& in : inputs_) {
      if (Inside(in.path, out.path)) {
        throw InputError(Quoted(out.flag, out.path) + " would replace the input " +
                         Quoted(in.flag, in.path) + " (the folder is replaced whole); choose " +
                         "another output folder");
      }
    }
  }
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

}  // namespace hexgait
