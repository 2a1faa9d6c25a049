// Two runs cannot write one folder at once: an exclusive flock() on a lock file inside the
// folder, held for the whole run. The kernel drops it when the process ends in any way
// (kill -9 included), so a stale lock file never blocks the next run. The file is removed when
// the lock is released; a run that locked a file just removed this way notices (the path no
// longer names its file) and locks the new one instead.
#pragma once

#include <string>

namespace hexgait {

inline constexpr const char* kLockFileName = ".hexgait-lock";

class FolderLock {
 public:
  // `what` names the option in the error; throws InputError naming the PID of the run that
  // holds the folder, or why the lock file cannot be made. The lock file is FOLDER/.hexgait-lock
  // unless `lock_file` names another (a folder replaced whole is locked from beside it).
  FolderLock(const std::string& folder, const std::string& what, const std::string& lock_file = "");
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
  int temp_handle_ = 0;
};

}  // namespace hexgait
