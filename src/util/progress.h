// The one progress hook every long call takes: how far it has come, `done` of `total` of
// `stage`, which names what is counted in the words a bar shows after the numbers ("steps",
// "frames", "evaluations", "trials", "GA generations"); `total` is 0 where it is not known in
// advance (a movie read frame by frame). A call with several parts reports each
// under its own stage. Called on the calling thread between chunks of work; it may throw (a
// stop, Python's KeyboardInterrupt) to end the call, which then leaves nothing half-written.
// A library never draws: the command draws its bar from this hook (util/progress_bar.h),
// Python checks its signals in it.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace hexgait {

using Progress = std::function<void(std::string_view stage, long long done, long long total)>;

// One finished line of a long call's log (a figure written, a benchmark's row measured), which
// the command prints as it comes.
using LogLine = std::function<void(const std::string& line)>;

}  // namespace hexgait
