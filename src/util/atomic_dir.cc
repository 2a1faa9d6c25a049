#include "util/output.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/error.h"
#include "util/folder_path.h"
#include "util/output.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace fs = std::filesystem;
namespace {

// True if `path` may be replaced: it does not exist, is empty, or carries `marker`.
bool Replaceable(const std::string& path, const std::string& marker) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return true;
  if (!fs::is_directory(path, ec)) return false;
  return fs::is_empty(path, ec) || fs::exists(fs::path(path) / marker, ec);
}

}  // namespace

AtomicDir::AtomicDir(std::string path, std::string marker, std::string what)
    : path_(NormalFolderPath(path)), marker_(std::move(marker)), what_(std::move(what)) {
  if (path_.empty()) throw InputError(what_ + ": empty folder name");
  std::error_code ec;
  if (fs::exists(path_, ec) && !fs::is_directory(path_, ec)) {
    throw InputError(what_ + " '" + path_ + "': is a file, expected a folder");
  }
  if (!Replaceable(path_, marker_)) {
    throw InputError(what_ + " '" + path_ + "': folder exists and was not written by hexgait (no " +
                     marker_ + "); choose a new or empty folder");
  }
  // The parent must exist and be writable (checked on the parent itself: a probe name beside
  // the folder could be taken by something the user never named).
  {
    const fs::path parent =
        fs::path(path_).has_parent_path() ? fs::path(path_).parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec)) {
      throw FileError(what_ + " '" + path_ + "': " +
                      (fs::exists(parent, ec) ? "'" + parent.string() + "' is a file, not a folder"
                                              : "folder '" + parent.string() + "' does not exist"));
    }
    if (::access(parent.c_str(), W_OK) != 0) {
      throw FileError(what_ + " '" + path_ + "': folder '" + parent.string() + "' is not writable");
    }
  }
  // The folder itself is swapped on Commit, so its lock file lives beside it (.NAME.hexgait-lock).
  const fs::path full(path_);
  std::string lock_name = full.filename().string();
  lock_name.insert(lock_name.begin(), '.');
  lock_name.append(kLockFileName);
  const fs::path lock_file = full.parent_path() / lock_name;
  lock_ = std::make_unique<FolderLock>(path_, what_, lock_file.string());
  temp_handle_ = CreateRegisteredTemp([&] {
    std::string pattern = path_ + ".partial.XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw InputError("cannot create a temporary folder next to '" + path_ +
                       "': " + std::strerror(errno));
    }
    temp_path_ = pattern;
    return pattern;
  });
  // mkdtemp makes the folder private (0700); the result should get the usual permissions.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(temp_path_.c_str(), 0777 & ~mask);
}

AtomicDir::~AtomicDir() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(temp_path_, ec);
  }
  if (temp_handle_ != 0) UnregisterTemp(temp_handle_);
}

void AtomicDir::Commit() {
  WriteFileAtomically(File(marker_), "written by hexgait; the next run may replace this folder\n");
  std::error_code ec;
  std::string old;
  CommitTemp([&] {
    // An old folder is moved aside first: rename() cannot replace a non-empty folder.
    if (fs::exists(path_, ec)) {
      if (!Replaceable(path_, marker_)) {
        throw InputError(what_ + " '" + path_ + "': folder changed while hexgait was writing");
      }
      old = path_ + ".old.XXXXXX";
      if (::mkdtemp(old.data()) == nullptr) {
        throw InputError("cannot create a folder next to '" + path_ + "': " + std::strerror(errno));
      }
      if (::rename(path_.c_str(), (old + "/d").c_str()) != 0) {
        const std::string why = std::strerror(errno);
        fs::remove(old, ec);
        throw InputError("cannot move the old '" + path_ + "' aside: " + why);
      }
    }
    if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      if (!old.empty()) ::rename((old + "/d").c_str(), path_.c_str());
      throw InputError("cannot move '" + temp_path_ + "' to '" + path_ + "': " + why);
    }
    committed_ = true;
  });
  if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace hexgait
