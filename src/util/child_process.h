// A child process started without a shell (posix_spawnp: PATH lookup, arguments as given).
// The destructor waits for it, so no child is ever left behind.
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace hexgait {

// Sends SIGTERM to every child still running and waits for them (at most 3 s, then SIGKILL):
// called by the stop watchdog (util/stop_signal.h) before the process exits.
void StopChildProcessesForExit();

class ChildProcess {
 public:
  enum class Stdout { kDiscard, kCapture };

  // Starts `argv[0]`. Its stdin reads from a pipe (input()) when `pipe_stdin`, else from
  // /dev/null; its stdout goes to /dev/null or to a pipe read by ReadOutput(); its stderr goes
  // to /dev/null unless `keep_stderr`. Throws InputError if it cannot start.
  ChildProcess(const std::vector<std::string>& argv, bool pipe_stdin, Stdout out = Stdout::kDiscard,
               bool keep_stderr = false);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  std::FILE* input() { return input_.get(); }
  // Everything the child writes to stdout until it closes it (Stdout::kCapture only).
  std::string ReadOutput();
  // Closes stdin, waits, and returns the exit status (128 + signal if killed); `peak_mib` gets
  // the child's peak resident memory.
  int Wait(double* peak_mib = nullptr);

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  pid_t pid_ = -1;
  std::unique_ptr<std::FILE, Closer> input_;
  std::unique_ptr<std::FILE, Closer> output_;
};

}  // namespace hexgait
