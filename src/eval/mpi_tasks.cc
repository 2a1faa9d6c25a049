#include "eval/mpi_tasks.h"

#include <cstring>
#include <exception>
#include <string>

#include "eval/mpi_evaluator.h"
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
  const int ranks = Mpi().world_size();
  size_t next = 0;
  int working = ranks - 1;  // ranks not yet told to stop
  while (working > 0) {
    const MpiMessage status = WaitForMessage(kMpiAny, kMpiAny);
    if (status.tag == kTagFailed) {
      std::string message(static_cast<size_t>(status.bytes), '\0');
      Mpi().receive(message.data(), status.bytes, kMpiBytes, status.source, kTagFailed);
      throw InputError("rank " + std::to_string(status.source) + ": " + message);
    }
    long long finished = kNone;
    Mpi().receive(&finished, 1, kMpiLongLong, status.source, kTagAsk);
    if (finished != kNone) on_done(finished);
    long long task = kNone;
    if (next < tasks.size()) {
      task = tasks[next++];
    } else {
      --working;
    }
    Mpi().send(&task, 1, kMpiLongLong, status.source, kTagTask);
  }
}

void JoinMpiTaskPool(const std::function<void(long long task)>& run) {
  if (!MpiIsWorker()) return;
  long long finished = kNone;
  for (;;) {
    Mpi().send(&finished, 1, kMpiLongLong, 0, kTagAsk);
    long long task = kNone;
    WaitForMessage(0, kTagTask);
    Mpi().receive(&task, 1, kMpiLongLong, 0, kTagTask);
    if (task == kNone) throw MpiWorkerDone{};
    try {
      run(task);
    } catch (const std::exception& e) {
      Mpi().send(e.what(), static_cast<int>(std::strlen(e.what())), kMpiBytes, 0, kTagFailed);
      throw MpiWorkerDone{};
    }
    finished = task;
  }
}

}  // namespace hexgait
