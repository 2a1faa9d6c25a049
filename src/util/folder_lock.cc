#include "util/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "util/error.h"

namespace hexgait {

FolderLock::FolderLock(const std::string& folder, const std::string& what,
                       const std::string& lock_file) {
  const std::string path = lock_file.empty() ? folder + "/" + kLockFileName : lock_file;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) {
    throw InputError(what + " '" + folder + "': cannot create the lock file " + kLockFileName +
                     ": " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char pid[32] = {};
    const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      std::string holder = n > 0 ? std::string(pid, static_cast<size_t>(n)) : "unknown";
      while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
      throw InputError(what + " '" + folder + "': another hexgait (PID " + holder +
                       ") is writing this folder; wait for it to finish or choose another folder");
    }
    throw InputError(what + " '" + folder + "': cannot lock " + kLockFileName + ": " +
                     std::strerror(error));
  }
  // The holder's PID, for the message another run gets.
  const std::string text = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) < 0) {
    // The lock holds without the PID; the other run's message then says "unknown".
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock; the file stays, harmless and reused
}

}  // namespace hexgait
