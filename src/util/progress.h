// The one progress hook every long call takes: how far it has come, `done` of `total` in the
// call's own units (simulation steps, movie frames, evaluations). Called on the calling thread
// between chunks of work; it may throw (a stop, Python's KeyboardInterrupt) to end the call,
// which then leaves nothing half-written. A library never draws: the command draws its bar from
// this hook (util/progress_bar.h), Python checks its signals in it.
#pragma once

#include <functional>

namespace hexgait {

using Progress = std::function<void(long long done, long long total)>;

}  // namespace hexgait
