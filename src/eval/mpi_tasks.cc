#include "eval/mpi_tasks.h"

#include <mpi.h>

#include <cstring>
#include <exception>
#include <string>

#include "eval/mpi_wait.h"
#include "util/error.h"

namespace hexgait {
namespace {

// Tags apart from the evaluator's (1-3), so the two protocols never take each other's messages.
constexpr int kTagAsk = 11;     // worker -> 0: the task it finished (-1: none yet)
constexpr int kTagTask = 12;    // 0 -> worker: the next task (-1: none left, stop)
constexpr int kTagFailed = 13;  // worker -> 0: the failed task's error message

constexpr long long kNone = -1;

}  // namespace

void MpiDispatchTasks(const std::vector<long long>& tasks,
                      const std::function<void(long long task)>& on_done) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  size_t next = 0;
  int working = ranks - 1;  // ranks not yet told to stop
  while (working > 0) {
    MPI_Status status;
    WaitForMessage(MPI_ANY_SOURCE, MPI_ANY_TAG, &status);
    if (status.MPI_TAG == kTagFailed) {
      int bytes = 0;
      MPI_Get_count(&status, MPI_CHAR, &bytes);
      std::string message(static_cast<size_t>(bytes), '\0');
      MPI_Recv(message.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kTagFailed, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      throw InputError("rank " + std::to_string(status.MPI_SOURCE) + ": " + message);
    }
    long long finished = kNone;
    MPI_Recv(&finished, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagAsk, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (finished != kNone) on_done(finished);
    long long task = kNone;
    if (next < tasks.size()) {
      task = tasks[next++];
    } else {
      --working;
    }
    MPI_Send(&task, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
  }
}

void MpiServeTasks(const std::function<void(long long task)>& run) {
  long long finished = kNone;
  for (;;) {
    MPI_Send(&finished, 1, MPI_LONG_LONG, 0, kTagAsk, MPI_COMM_WORLD);
    long long task = kNone;
    MPI_Status status;
    WaitForMessage(0, kTagTask, &status);
    MPI_Recv(&task, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (task == kNone) return;
    try {
      run(task);
    } catch (const std::exception& e) {
      MPI_Send(e.what(), static_cast<int>(std::strlen(e.what())), MPI_CHAR, 0, kTagFailed,
               MPI_COMM_WORLD);
      return;
    }
    finished = task;
  }
}

}  // namespace hexgait
