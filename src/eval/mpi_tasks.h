// Whole independent tasks (one evolve run per seed, for `hexgait sweep`) handed out to MPI
// ranks as they become free: rank 0 dispatches, every other rank asks for a task, runs it, and
// asks again. Called only when mpirun launched the process with more than one rank.
#pragma once

#include <functional>
#include <vector>

namespace hexgait {

// Rank 0: hands each task of `tasks` to the next rank that asks, calls `on_done(task)` as each
// is reported finished, and returns when all are done and every other rank has been released.
// Throws InputError with the rank's message if a task fails there.
void MpiDispatchTasks(const std::vector<long long>& tasks,
                      const std::function<void(long long task)>& on_done);

// Called by every rank before rank 0 dispatches. On a worker rank: runs `run(task)` for each task
// rank 0 hands it until none is left (an exception from `run` is sent to rank 0, which stops the
// job), then throws MpiWorkerDone (eval/mpi_evaluator.h). On rank 0, and without MPI, returns
// at once.
void JoinMpiTaskPool(const std::function<void(long long task)>& run);

}  // namespace hexgait
