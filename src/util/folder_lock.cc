#include "util/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "util/error.h"
#include "util/temp_registry.h"

namespace hexgait {

namespace {

// True if `path` still names the open file `fd` (not removed or replaced since it was opened).
bool StillNamed(int fd, const std::string& path) {
  struct stat open_file {
  }, named{};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 &&
         open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

}  // namespace

FolderLock::FolderLock(const std::string& folder, const std::string& what,
                       const std::string& lock_file)
    : path_(lock_file.empty() ? folder + "/" + kLockFileName : lock_file) {
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) {
      throw InputError(what + " '" + folder + "': cannot create the lock file " + path_ + ": " +
                       std::strerror(errno));
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      char pid[32] = {};
      const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK) {
        std::string holder = n > 0 ? std::string(pid, static_cast<size_t>(n)) : "unknown";
        while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) {
          holder.pop_back();
        }
        throw InputError(what + " '" + folder + "': another hexgait (PID " + holder +
                         ") is writing this folder; wait for it to finish or choose another "
                         "folder");
      }
      throw InputError(what + " '" + folder + "': cannot lock " + path_ + ": " +
                       std::strerror(error));
    }
    if (StillNamed(fd_, path_)) break;
    ::close(fd_);  // the previous holder removed it between our open and flock: again
  }
  // The holder's PID, for the message another run gets.
  const std::string text = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) < 0) {
    // The lock holds without the PID; the other run's message then says "unknown".
  }
  // A command stopped by a signal exits without unwinding: the watchdog removes the file then.
  temp_handle_ = RegisterTemp(path_);
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  UnregisterTemp(temp_handle_);
  // Removed while still locked, so no other run can lock this file after it is gone.
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace hexgait
