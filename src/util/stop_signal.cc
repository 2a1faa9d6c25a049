#include "util/stop_signal.h"

#include <csignal>

namespace hexgait {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void OnStopSignal(int signal) {
  if (g_signal != 0) {
    // The second signal: stop now, with the default action (terminate).
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_signal = signal;
}

}  // namespace

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
