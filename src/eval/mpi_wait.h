// Waiting for an MPI message without spinning. Included only by the MPI backend's sources.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace hexgait {

// Blocking MPI calls spin on a core while they wait (OpenMPI polls), so a rank waiting for
// work or results would take a core from ranks still computing on the same node. Poll and
// sleep instead: a message is seen at most about a millisecond late, against seconds of
// compute per generation.
inline void WaitForMessage(int source, int tag, MPI_Status* status) {
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    int arrived = 0;
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, status);
    if (arrived) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

}  // namespace hexgait
