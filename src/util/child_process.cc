#include "util/child_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <thread>

#include "util/clock.h"
#include "util/error.h"
#include "util/process_usage.h"

extern char** environ;

namespace hexgait {
namespace {

// A pipe whose two ends are closed on scope exit unless released.
struct Pipe {
  int fd[2] = {-1, -1};
  ~Pipe() {
    for (int f : fd)
      if (f >= 0) close(f);
  }
  int Release(int end) {
    const int f = fd[end];
    fd[end] = -1;
    return f;
  }
};

// posix_spawn_file_actions_t with its destroy call.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
};

}  // namespace

namespace {

// Children still running, so a stopped parent can stop them before it exits (a `bench movie`
// stopped while its `hexgait render` runs must not leave that child writing on).
std::mutex children_mutex;
std::set<pid_t> children;

bool exiting = false;  // guarded by children_mutex: StopChildProcessesForExit has begun
void Untrack(pid_t pid) {
  std::lock_guard<std::mutex> lock(children_mutex);
  children.erase(pid);
}

}  // namespace

void StopChildProcessesForExit() {
  std::set<pid_t> running;
  {
    std::lock_guard<std::mutex> lock(children_mutex);
    exiting = true;
    running = children;
  }
  for (pid_t pid : running) kill(pid, SIGTERM);
  // Every command stops within about a second and removes its own temporaries; a child that
  // does not within 3 s is killed.
  const auto deadline = Clock::now() + std::chrono::seconds(3);
  for (pid_t pid : running) {
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (Clock::now() > deadline) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, bool pipe_stdin, Stdout out,
                           bool keep_stderr) {
  if (argv.empty()) throw InputError("cannot start a process without a program name");
  Pipe in, capture;
  if (pipe_stdin && pipe2(in.fd, O_CLOEXEC) != 0) throw InputError("cannot make a pipe");
  if (out == Stdout::kCapture && pipe2(capture.fd, O_CLOEXEC) != 0) {
    throw InputError("cannot make a pipe");
  }
  FileActions file;
  if (pipe_stdin) {
    posix_spawn_file_actions_adddup2(&file.actions, in.fd[0], STDIN_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&file.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  }
  if (out == Stdout::kCapture) {
    posix_spawn_file_actions_adddup2(&file.actions, capture.fd[1], STDOUT_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&file.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  }
  if (!keep_stderr) {
    posix_spawn_file_actions_addopen(&file.actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  {
    // Started and tracked under one lock: a stop that is stopping the children cannot miss one
    // started meanwhile, which would write on after this process is gone. Once the stop began,
    // no child starts; this thread waits for the exit.
    std::unique_lock<std::mutex> lock(children_mutex);
    while (exiting) {
      lock.unlock();
      std::this_thread::sleep_for(std::chrono::seconds(1));
      lock.lock();
    }
    if (posix_spawnp(&pid_, args[0], &file.actions, nullptr, args.data(), environ) != 0) {
      pid_ = -1;
      throw InputError("cannot start '" + argv[0] + "'");
    }
    children.insert(pid_);
  }
  // The parent keeps only its own ends, so the child sees end-of-file when we close ours.
  if (pipe_stdin) {
    input_.reset(fdopen(in.Release(1), "wb"));
    if (!input_) throw InputError("cannot open the pipe to '" + argv[0] + "'");
  }
  if (out == Stdout::kCapture) {
    output_.reset(fdopen(capture.Release(0), "rb"));
    if (!output_) throw InputError("cannot open the pipe from '" + argv[0] + "'");
  }
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) Wait();
}

std::string ChildProcess::ReadOutput() {
  std::string text;
  if (!output_) return text;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, output_.get())) > 0) text.append(buffer, n);
  return text;
}

int ChildProcess::Wait(double* peak_mib) {
  input_.reset();
  output_.reset();
  if (pid_ <= 0) return 128;
  int status = 0;
  rusage usage{};
  while (wait4(pid_, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  Untrack(pid_);
  pid_ = -1;
  if (peak_mib) *peak_mib = PeakResidentMiB(usage);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 128;
}

}  // namespace hexgait
