// A build without MPI: one rank, so tasks are never handed out to others (eval/mpi_tasks.h).
#include "eval/mpi_tasks.h"
#include "util/error.h"

namespace hexgait {

void MpiDispatchTasks(const std::vector<long long>&, const std::function<void(long long)>&) {
  throw InputError("this hexgait was built without MPI");
}

void MpiServeTasks(const std::function<void(long long)>&) {
  throw InputError("this hexgait was built without MPI");
}

}  // namespace hexgait
