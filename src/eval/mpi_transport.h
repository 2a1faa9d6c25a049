// The message passing the MPI backend needs, as a table of plain functions. Only the module that
// fills it (libhexgait_mpi.so, built from mpi_transport_module.cc) links the MPI library, and
// hexgait opens that module only when mpirun launched it (MpiInitIfLaunched): a plain run never
// loads Open MPI. Every call is rank 0's main thread or a worker rank's (MPI_THREAD_FUNNELED).
#pragma once

namespace hexgait {

// What a message carries, for the MPI datatype.
enum MpiItem : int { kMpiBytes = 0, kMpiLongLong = 1, kMpiDouble = 2 };
// Any source or tag in `probe`.
inline constexpr int kMpiAny = -1;

struct MpiTransport {
  int version;  // kMpiTransportVersion: a module from another build is refused
  // MPI_Init_thread(FUNNELED); 0 when it succeeded.
  int (*init)(int* argc, char*** argv);
  void (*finalize)();
  void (*abort)(int code);
  int (*world_size)();
  int (*rank)();
  void (*send)(const void* data, int count, int item, int destination, int tag);
  void (*receive)(void* data, int count, int item, int source, int tag);
  // Whether a message from `source` with `tag` (kMpiAny: any) is waiting; if so, sets its
  // source, tag and size in bytes. Never blocks.
  bool (*probe)(int source, int tag, int* found_source, int* found_tag, int* bytes);
};

inline constexpr int kMpiTransportVersion = 1;
// The module's one exported symbol.
#define HEXGAIT_MPI_TRANSPORT_SYMBOL "hexgait_mpi_transport"
#define HEXGAIT_MPI_MODULE_FILE "libhexgait_mpi.so"

}  // namespace hexgait

namespace hexgait {

// The transport of the job this process joined (MpiInitIfLaunched); only called when
// MpiWorldSize() > 1.
const MpiTransport& Mpi();

}  // namespace hexgait
