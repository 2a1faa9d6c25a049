// Ctrl-C (SIGINT) and SIGTERM during a long run: the first one sets a flag that long loops
// poll at safe points (between video frames, after a generation's checkpoint), so the run
// stops cleanly, keeps what is done and says how to go on. A second signal ends the process
// at once, as the user evidently means it.
#pragma once

#include <string>

#include "util/error.h"

namespace hexgait {

void InstallStopHandlers();
bool StopRequested();

// Long loops say how far apart their safe points are (the evaluator: its longest batch of the
// last population), so the first signal's acknowledgement can say how soon the stop comes
// ("stopping within about 0.4 s"). 0 or never called: the acknowledgement names no time.
void NoteSafePointInterval(double seconds);

// Commands without safe points (simulate, still, figures, bench, ...) must stop on the first
// signal too. The watchdog, a thread started once in main, notices the first signal within
// 50 ms; unless the running command has called StopIsPolled() (it stops itself at its safe
// points, like evolve after a generation's checkpoint), it removes every temporary file and
// folder of writes in progress (util/temp_registry), says so on stderr and exits with
// StopExitCode(). Outputs are only ever renamed into place, so nothing is half-written.
void StartStopWatchdog();
void StopIsPolled();
// For an error caught while a stop is under way, which may be only the stop's doing (the
// watchdog stopped a child process the command was waiting for): if the watchdog is ending
// the process, waits for it to (it exits with StopExitCode(), temporaries removed) rather than
// let the error race it to a different exit status. Returns at once otherwise.
void AwaitStopWatchdog();
// "SIGINT" or "SIGTERM" once a stop was requested.
std::string StopSignalName();
// Exit status for a run stopped by a signal: 128 + the signal number, as shells report it.
int StopExitCode();

// Thrown at a safe point after a stop request; the message says what was kept.
class Stopped : public InputError {
 public:
  explicit Stopped(const std::string& message) : InputError(message) {}
};

// For a host with its own SIGINT handler (the Python module). While one lives, SIGINT also asks
// hexgait's loops to stop (StopRequested: the evaluator polls it every 40 steps, a movie every
// frame), then runs the host's handler as before, so the host still hears of it; a host that
// ignores SIGINT is not asked to stop. When the last one ends, the host's handler is back and the
// request is cleared. Several at once (nested or on threads) share one installation; make them
// on the thread the host handles signals on.
class ForwardedStop {
 public:
  ForwardedStop();
  ~ForwardedStop();
  ForwardedStop(const ForwardedStop&) = delete;
  ForwardedStop& operator=(const ForwardedStop&) = delete;
};

// For tests: pretend a signal arrived (or clear it).
void RequestStopForTesting(bool stop);

}  // namespace hexgait
