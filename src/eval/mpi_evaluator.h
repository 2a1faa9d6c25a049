// The MPI backend. Its message passing lives in a module (libhexgait_mpi.so, built when MPI is
// found: eval/mpi_transport.h) that only a process launched by mpirun loads; otherwise these
// functions describe a world of one rank and the evaluator functions are never called.
// Rank 0 runs the optimizer and calls Evaluate;
// every rank, rank 0 included, evaluates a contiguous share of the tables with its own local
// evaluator (threads, batched kernels), and rank 0 gathers the results in order. Results do not
// depend on which rank ran which table (eval/evaluator.h), so a run is byte-identical to the
// same run without MPI for any rank and thread count.
//
// Only rank 0's main thread calls MPI (MPI_THREAD_FUNNELED). Errors are fatal (MPI's default
// handler): if a rank dies, mpirun stops the whole job; every file rank 0 writes is written
// atomically, so the last generation's checkpoint stays intact and `evolve --resume` goes on.
#pragma once

#include <memory>
#include <vector>

#include "eval/evaluator.h"

namespace hexgait {

// Whether this build has the MPI backend (hexgait --version says so).
bool MpiBuiltIn();

// Thrown on a worker rank (any rank but 0 of an MPI job) when its work for the command is done:
// by MakeEvaluator and MakeMpiEvaluator once rank 0's evaluator is gone, by JoinMpiTaskPool
// (eval/mpi_tasks.h) once no task is left. It ends the command there; main exits 0 on it. Not
// a std::exception, so no handler for errors takes it for one.
struct MpiWorkerDone {};

// Whether this process is a worker rank. Only the command-line layer asks, to leave workers out
// of the commands that are not distributed; commands never do.
bool MpiIsWorker();

// Starts MPI when this process was launched by mpirun (else does nothing); safe to call once.
// A worker rank's stdout and stderr go to /dev/null: only rank 0 talks to the user.
void MpiInitIfLaunched(int* argc, char*** argv);
void MpiFinalize();
// Stops every rank of the job with `code` (MPI_Abort).
void MpiAbort(int code);
// 1 and 0 when MPI is not running.
int MpiWorldSize();
int MpiRank();

// Where the last Evaluate call's time went, for `bench scale`: rank 0's sending, each rank's
// evaluation (rank 0 first), and the bytes that crossed between ranks.
struct MpiTimings {
  double seconds_total = 0;
  double seconds_send = 0;              // rank 0 handing out the tables
  std::vector<double> seconds_compute;  // per rank, measured by that rank
  long long bytes_sent = 0, bytes_received = 0;
};

// On rank 0, the evaluator across ranks; its destructor releases the other ranks. With
// `timings`, each Evaluate call fills it. On a worker rank it does not return: it evaluates
// what rank 0 sends, with `config`'s threads and kernels, until rank 0's evaluator is
// destroyed, then throws MpiWorkerDone.
std::unique_ptr<Evaluator> MakeMpiEvaluator(const CreatureModel& model, const MotorProgram& program,
                                            const EvaluatorConfig& config,
                                            MpiTimings* timings = nullptr);

}  // namespace hexgait
