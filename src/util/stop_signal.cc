#include "util/stop_signal.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>

#include "util/child_process.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

volatile std::sig_atomic_t g_signal = 0;

std::atomic<bool> g_polled{false};  // lock-free: read in the signal handler

// A command that stops at its safe points says at once that it heard the first signal: the
// safe point may be seconds away. write(2) is async-signal-safe; stdio is not.
void Acknowledge(int signal) {
  static constexpr char kInt[] =
      "\nhexgait: SIGINT received: stopping at the next safe point (the end of the current "
      "generation, batch or frame); press Ctrl-C again to stop at once\n";
  static constexpr char kTerm[] =
      "\nhexgait: SIGTERM received: stopping at the next safe point (the end of the current "
      "generation, batch or frame); send it again to stop at once\n";
  const char* text = signal == SIGTERM ? kTerm : kInt;
  const size_t size = signal == SIGTERM ? sizeof kTerm - 1 : sizeof kInt - 1;
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, text, size);
}

extern "C" void OnStopSignal(int signal) {
  if (g_signal != 0) {
    // The second signal: stop now, with the default action (terminate).
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_signal = signal;
  if (g_polled.load(std::memory_order_relaxed)) Acknowledge(signal);
}

std::atomic<bool> g_watchdog{false};  // started

}  // namespace

void StopIsPolled() {
  g_polled = true;
}

void AwaitStopWatchdog() {
  if (!StopRequested() || g_polled || !g_watchdog) return;
  for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // until the watchdog exits
}

void StartStopWatchdog() {
  g_watchdog = true;
  std::thread([] {
    while (!StopRequested() || g_polled) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    StopChildProcessesForExit();
    RemoveAllTempsForExit();
    std::fprintf(stderr,
                 "\nhexgait: stopped by %s; unfinished outputs removed, earlier files "
                 "unchanged\n",
                 StopSignalName().c_str());
    std::fflush(stderr);
    ::_exit(StopExitCode());
  }).detach();
}

void InstallStopHandlers() {
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool StopRequested() {
  return g_signal != 0;
}

std::string StopSignalName() {
  return g_signal == SIGTERM ? "SIGTERM" : "SIGINT";
}

int StopExitCode() {
  return 128 + (g_signal != 0 ? static_cast<int>(g_signal) : SIGINT);
}

void RequestStopForTesting(bool stop) {
  g_signal = stop ? SIGINT : 0;
}

}  // namespace hexgait
