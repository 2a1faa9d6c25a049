// Independent pieces of work spread over threads: the pattern of the commands that run many
// whole simulations side by side (endurance's traces, adapt's library runs, sweep's seeds),
// written once.
#pragma once

#include <cstddef>
#include <functional>

namespace hexgait {

// Calls work(i) once for every i in [0, count), on up to `threads` threads (at least one), the
// calling thread among them. After the first exception no new i is handed out; it is rethrown
// once every thread has finished. `work` must not depend on which thread runs it.
void ParallelFor(size_t count, int threads, const std::function<void(size_t)>& work);

}  // namespace hexgait
