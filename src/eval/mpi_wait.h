// Waiting for an MPI message without spinning. Included only by the MPI backend's sources.
#pragma once

#include <algorithm>
#include <chrono>
#include <thread>

#include "eval/mpi_transport.h"

namespace hexgait {

struct MpiMessage {
  int source = 0, tag = 0, bytes = 0;
};

// Blocking MPI calls spin on a core while they wait (OpenMPI polls), so a rank waiting for
// work or results would take a core from ranks still computing on the same node. Poll and
// sleep instead: a message is seen at most about a millisecond late, against seconds of
// compute per generation.
inline MpiMessage WaitForMessage(int source, int tag) {
  auto pause = std::chrono::microseconds(20);
  MpiMessage message;
  while (!Mpi().probe(source, tag, &message.source, &message.tag, &message.bytes)) {
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
  return message;
}

}  // namespace hexgait
