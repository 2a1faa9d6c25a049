// libhexgait_mpi.so: the MPI transport (eval/mpi_transport.h) over the MPI C API. Nothing else
// of hexgait is in this module, so it links only libmpi, and only a process that mpirun
// launched ever loads it.
#include <mpi.h>

#include "eval/mpi_transport.h"

namespace {

MPI_Datatype Datatype(int item) {
  switch (item) {
    case hexgait::kMpiLongLong:
      return MPI_LONG_LONG;
    case hexgait::kMpiDouble:
      return MPI_DOUBLE;
    default:
      return MPI_CHAR;
  }
}

int Init(int* argc, char*** argv) {
  int provided = 0;
  return MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) == MPI_SUCCESS ? 0 : 1;
}

void Finalize() {
  MPI_Finalize();
}

void Abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
}

int WorldSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

int Rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

void Send(const void* data, int count, int item, int destination, int tag) {
  MPI_Send(data, count, Datatype(item), destination, tag, MPI_COMM_WORLD);
}

void Receive(void* data, int count, int item, int source, int tag) {
  MPI_Recv(data, count, Datatype(item), source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

bool Probe(int source, int tag, int* found_source, int* found_tag, int* bytes) {
  MPI_Status status;
  int arrived = 0;
  MPI_Iprobe(source == hexgait::kMpiAny ? MPI_ANY_SOURCE : source,
             tag == hexgait::kMpiAny ? MPI_ANY_TAG : tag, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return false;
  *found_source = status.MPI_SOURCE;
  *found_tag = status.MPI_TAG;
  MPI_Get_count(&status, MPI_CHAR, bytes);
  return true;
}

const hexgait::MpiTransport kTransport = {
    hexgait::kMpiTransportVersion, Init, Finalize, Abort, WorldSize, Rank, Send, Receive, Probe};

}  // namespace

extern "C" __attribute__((visibility("default"))) const hexgait::MpiTransport*
hexgait_mpi_transport() {
  return &kTransport;
}
