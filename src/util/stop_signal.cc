#include "util/stop_signal.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <mutex>
#include <thread>

#include "util/child_process.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

volatile std::sig_atomic_t g_signal = 0;

std::atomic<bool> g_polled{false};  // lock-free: read in the signal handler

std::atomic<int> g_interval_ms{0};  // lock-free: read in the signal handler

// Appends `text` to buf at *at, leaving room for the terminating zero; async-signal-safe.
void Append(char* buf, size_t size, size_t* at, const char* text) {
  for (; *text != 0 && *at + 1 < size; ++text) buf[(*at)++] = *text;
}

// "0.4" for 400 ms, "12" for 12,300 ms: one decimal below 10 s. Async-signal-safe.
void AppendSeconds(char* buf, size_t size, size_t* at, int ms) {
  const int tenths = (ms + 99) / 100;  // rounded up: the stop comes no later than it says
  char digits[16];
  int n = 0;
  int whole = tenths >= 100 ? (tenths + 9) / 10 : tenths / 10;
  do {
    digits[n++] = static_cast<char>('0' + whole % 10);
    whole /= 10;
  } while (whole > 0 && n < 15);
  while (n > 0 && *at + 1 < size) buf[(*at)++] = digits[--n];
  if (tenths < 100 && *at + 3 < size) {
    buf[(*at)++] = '.';
    buf[(*at)++] = static_cast<char>('0' + tenths % 10);
  }
}

// A command that stops at its safe points says at once that it heard the first signal, and how
// soon the stop comes when its loop said (NoteSafePointInterval): the safe point may be seconds
// away. write(2) is async-signal-safe; stdio and std::string are not, hence the fixed buffer.
void Acknowledge(int signal) {
  char text[256];
  size_t at = 0;
  Append(text, sizeof text, &at,
         signal == SIGTERM ? "\nhexgait: SIGTERM received: stopping "
                           : "\nhexgait: SIGINT received: stopping ");
  const int ms = g_interval_ms.load(std::memory_order_relaxed);
  if (ms > 0) {
    Append(text, sizeof text, &at, "within about ");
    AppendSeconds(text, sizeof text, &at, ms);
    Append(text, sizeof text, &at, " s, at the end of the simulations under way");
  } else {
    Append(text, sizeof text, &at,
           "at the next safe point (the end of the current generation, batch or frame)");
  }
  Append(text, sizeof text, &at,
         signal == SIGTERM ? "; send it again to stop at once\n"
                           : "; press Ctrl-C again to stop at once\n");
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, text, at);
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

// ForwardedStop: the host's SIGINT action, saved before ours is installed (so the handler only
// reads it), and how many ForwardedStops live.
struct sigaction g_host_action {};
std::mutex g_forward_mutex;
int g_forwards = 0;

extern "C" void OnForwardedSignal(int signal, siginfo_t* info, void* context) {
  const struct sigaction& host = g_host_action;
  if (host.sa_flags & SA_SIGINFO) {
    if (g_signal == 0) g_signal = signal;
    host.sa_sigaction(signal, info, context);
  } else if (host.sa_handler == SIG_IGN) {
    // The host ignores it: so does hexgait.
  } else if (host.sa_handler == SIG_DFL) {
    std::signal(signal, SIG_DFL);  // the default action: the process ends by it
    std::raise(signal);
  } else {
    if (g_signal == 0) g_signal = signal;
    host.sa_handler(signal);
  }
}

}  // namespace

ForwardedStop::ForwardedStop() {
  std::lock_guard<std::mutex> lock(g_forward_mutex);
  if (g_forwards++ > 0) return;
  struct sigaction ours {};
  ours.sa_sigaction = OnForwardedSignal;
  ours.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&ours.sa_mask);
  sigaction(SIGINT, nullptr, &g_host_action);  // saved before ours can run
  sigaction(SIGINT, &ours, nullptr);
}

ForwardedStop::~ForwardedStop() {
  std::lock_guard<std::mutex> lock(g_forward_mutex);
  if (--g_forwards > 0) return;
  sigaction(SIGINT, &g_host_action, nullptr);
  g_signal = 0;
}

void NoteSafePointInterval(double seconds) {
  const double ms = seconds * 1000.0;
  g_interval_ms.store(ms > 0 ? static_cast<int>(std::min(ms, 3.6e6)) : 0,
                      std::memory_order_relaxed);
}

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
