// Output files appear whole or not at all: content goes to a temporary file in the same
// folder, which is renamed over the final name only once it is complete and flushed.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace hexgait {

// Owns a temporary file next to `path`; Commit() renames it into place. If the object is
// destroyed without Commit() (an error, an exception), the temporary file is removed.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws InputError if the folder is not writable
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* handle() { return file_.get(); }
  const std::string& temp_path() const { return temp_path_; }
  void Write(std::string_view text);
  void Commit();  // throws InputError on a failed write, flush or rename

 private:
  struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::string path_;
  std::string temp_path_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  bool failed_ = false;
  int temp_handle_ = 0;  // in util/temp_registry, so a stop signal removes the file
};

// Convenience: writes `text` to `path` atomically.
void WriteFileAtomically(const std::string& path, std::string_view text);

// Checks before any work starts that `path` can be created: its folder exists and is writable.
void CheckOutputPath(const std::string& path, const std::string& what);

}  // namespace hexgait
