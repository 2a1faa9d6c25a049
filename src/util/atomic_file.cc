#include "util/output.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "util/error.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

std::string ParentFolder(const std::string& path) {
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

void CheckOutputPath(const std::string& path, const std::string& what) {
  if (path.empty()) throw FileError(what + ": empty output path");
  // Outputs are replaced by renaming a temporary file over them, which would turn a device, a
  // FIFO or a link such as /proc/self/fd/1 into a regular file (as root, /dev/null too): only a
  // regular file or a new name may be an output.
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      throw FileError(what + " '" + path + "': is a directory, expected a file name");
    }
    if (S_ISLNK(st.st_mode)) {
      throw FileError(what + " '" + path +
                      "': is a symbolic link; writing would replace the link, not its target "
                      "(give the target's path)");
    }
    if (!S_ISREG(st.st_mode)) {
      throw FileError(what + " '" + path +
                      "': not a regular file (a device, FIFO or socket); outputs are written "
                      "as new regular files only");
    }
  }
  std::error_code ec;
  const std::string folder = ParentFolder(path);
  if (!std::filesystem::is_directory(folder, ec)) {
    throw FileError(what + " '" + path + "': " +
                    (std::filesystem::exists(folder, ec)
                         ? "'" + folder + "' is a file, not a folder"
                         : "folder '" + folder + "' does not exist"));
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw FileError(what + " '" + path + "': folder '" + folder + "' is not writable");
  }
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  CheckOutputPath(path_, "output file");
  // mkstemp gives a unique name in the same folder, so the final rename stays atomic.
  int fd = -1;
  temp_handle_ = CreateRegisteredTemp([&] {
    std::string pattern = path_ + ".partial.XXXXXX";
    fd = ::mkstemp(pattern.data());
    if (fd < 0) {
      throw FileError("cannot create a temporary file next to '" + path_ +
                      "': " + std::strerror(errno));
    }
    temp_path_ = pattern;
    return pattern;
  });
  file_.reset(::fdopen(fd, "wb"));
  if (!file_) {
    ::close(fd);
    std::remove(temp_path_.c_str());
    throw FileError("cannot open '" + temp_path_ + "': " + std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (file_) {
    file_.reset();
    std::remove(temp_path_.c_str());
  }
  if (temp_handle_ != 0) UnregisterTemp(temp_handle_);
}

void AtomicFile::Write(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size()) failed_ = true;
}

void AtomicFile::Commit() {
  std::FILE* f = file_.get();
  if (failed_ || std::ferror(f) || std::fflush(f) != 0 || ::fsync(::fileno(f)) != 0) {
    const std::string reason = std::strerror(errno);
    throw StorageError("writing '" + path_ + "' failed: " + reason);
  }
  // Mode 0644 like an ordinary file, not mkstemp's 0600.
  ::fchmod(::fileno(f), 0644);
  file_.reset();
  CommitTemp([&] {
    if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      std::remove(temp_path_.c_str());
      throw FileError("cannot rename '" + temp_path_ + "' to '" + path_ + "': " + reason);
    }
  });
}

void WriteFileAtomically(const std::string& path, std::string_view text) {
  AtomicFile file(path);
  file.Write(text);
  file.Commit();
}

}  // namespace hexgait
