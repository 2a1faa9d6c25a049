#include "eval/mpi_evaluator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "eval/mpi_transport.h"
#include "eval/mpi_wait.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/shared_library.h"

namespace hexgait {

bool MpiBuiltIn() {
#ifdef HEXGAIT_MPI_MODULE
  return true;
#else
  return false;
#endif
}

namespace {

// Every share runs whole: rank 0 must collect each result it handed out, and a worker rank
// that stopped half-way would leave it waiting. A stop under mpirun comes after the population.
EvaluatorConfig WholeBatches(EvaluatorConfig config) {
  config.stop_on_request = false;
  return config;
}

constexpr int kTagHeader = 1;
constexpr int kTagTables = 2;
constexpr int kTagResults = 3;

// The joined job's transport; nullptr when mpirun did not launch this process.
const MpiTransport* g_mpi = nullptr;

// Rank `rank`'s share of `count` tables: [Begin(rank), Begin(rank + 1)). Contiguous and fixed
// by (count, ranks) alone.
int Begin(int count, int ranks, int rank) {
  return static_cast<int>(static_cast<long long>(count) * rank / ranks);
}

// RunResult as bytes: every field, in declaration order; the reason as length + characters.
template <class T>
void Put(std::vector<char>& out, const T& value) {
  const char* p = reinterpret_cast<const char*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}
template <class T>
void Get(const std::vector<char>& in, size_t& at, T& value) {
  std::memcpy(&value, in.data() + at, sizeof(T));
  at += sizeof(T);
}

void PutResult(std::vector<char>& out, const RunResult& r) {
  Put(out, r.distance), Put(out, r.fell), Put(out, r.fall_time), Put(out, r.fall_cycle);
  Put(out, r.steps), Put(out, r.end_time), Put(out, r.diverged), Put(out, r.diverge_time);
  Put(out, r.diverge_step);
  Put(out, static_cast<long long>(r.diverge_reason.size()));
  out.insert(out.end(), r.diverge_reason.begin(), r.diverge_reason.end());
  Put(out, r.min_body_height), Put(out, r.max_tilt_degrees), Put(out, r.mean_feet_on_ground);
  Put(out, r.feet_samples), Put(out, r.stopped_early), Put(out, r.foot_down_checks);
}

RunResult GetResult(const std::vector<char>& in, size_t& at) {
  RunResult r;
  Get(in, at, r.distance), Get(in, at, r.fell), Get(in, at, r.fall_time);
  Get(in, at, r.fall_cycle), Get(in, at, r.steps), Get(in, at, r.end_time);
  Get(in, at, r.diverged), Get(in, at, r.diverge_time), Get(in, at, r.diverge_step);
  long long length = 0;
  Get(in, at, length);
  r.diverge_reason.assign(in.data() + at, static_cast<size_t>(length));
  at += static_cast<size_t>(length);
  Get(in, at, r.min_body_height), Get(in, at, r.max_tilt_degrees);
  Get(in, at, r.mean_feet_on_ground), Get(in, at, r.feet_samples), Get(in, at, r.stopped_early);
  Get(in, at, r.foot_down_checks);
  return r;
}

// Header: count (-1: stop), springs, positions.
struct Header {
  long long count = 0, springs = 0, positions = 0;
};

class MpiEvaluator final : public Evaluator {
 public:
  MpiEvaluator(const CreatureModel& model, const MotorProgram& program,
               const EvaluatorConfig& config, MpiTimings* timings)
      : local_(MakeLocalEvaluator(model, program, WholeBatches(config))),
        ranks_(MpiWorldSize()),
        timings_(timings) {}
  ~MpiEvaluator() override {
    Header stop{-1, 0, 0};
    for (int r = 1; r < ranks_; ++r) {
      Mpi().send(&stop, 3, kMpiLongLong, r, kTagHeader);
    }
  }

  std::vector<RunResult> Evaluate(std::span<const RestLengthTable> tables,
                                  const Progress& on_progress) override {
    const auto start = Clock::now();
    MpiTimings t;
    t.seconds_compute.assign(static_cast<size_t>(ranks_), 0.0);
    const int count = static_cast<int>(tables.size());
    // Hand out every other rank's share first, so they run while rank 0 runs its own.
    for (int r = 1; r < ranks_; ++r) {
      const int begin = Begin(count, ranks_, r), end = Begin(count, ranks_, r + 1);
      Header h{end - begin, 0, 0};
      std::vector<double> flat;
      if (end > begin) {
        h.springs = tables[begin].num_springs;
        h.positions = tables[begin].num_positions;
        for (int k = begin; k < end; ++k) {
          flat.insert(flat.end(), tables[k].length.begin(), tables[k].length.end());
        }
      }
      Mpi().send(&h, 3, kMpiLongLong, r, kTagHeader);
      if (end > begin) {
        Mpi().send(flat.data(), static_cast<int>(flat.size()), kMpiDouble, r, kTagTables);
      }
      t.bytes_sent += static_cast<long long>(sizeof h + flat.size() * sizeof(double));
    }
    t.seconds_send = SecondsSince(start);
    const int mine = Begin(count, ranks_, 1);
    const auto own_start = Clock::now();
    std::vector<RunResult> results = local_->Evaluate(
        tables.first(mine), [&](std::string_view stage, long long done, long long) {
          if (on_progress) on_progress(stage, done, count);  // the others' progress is not seen
        });
    t.seconds_compute[0] = SecondsSince(own_start);
    results.reserve(tables.size());
    for (int r = 1; r < ranks_; ++r) {
      const int begin = Begin(count, ranks_, r), end = Begin(count, ranks_, r + 1);
      if (end == begin) continue;
      const int bytes = WaitForMessage(r, kTagResults).bytes;
      std::vector<char> buffer(static_cast<size_t>(bytes));
      Mpi().receive(buffer.data(), bytes, kMpiBytes, r, kTagResults);
      // First byte: 0 results follow, 1 an error message follows (the worker's exception).
      if (buffer.empty() || buffer[0] != 0) {
        throw InputError("rank " + std::to_string(r) + ": " +
                         std::string(buffer.begin() + (buffer.empty() ? 0 : 1), buffer.end()));
      }
      t.bytes_received += bytes;
      size_t at = 1;
      for (int k = begin; k < end; ++k) results.push_back(GetResult(buffer, at));
      Get(buffer, at, t.seconds_compute[static_cast<size_t>(r)]);
      if (on_progress) on_progress("evaluations", end, count);
    }
    t.seconds_total = SecondsSince(start);
    if (timings_) *timings_ = std::move(t);
    return results;
  }

  std::string Describe() const override {
    return "MPI, " + std::to_string(ranks_) + " ranks, each " + local_->Describe();
  }

 private:
  std::unique_ptr<Evaluator> local_;
  int ranks_;
  MpiTimings* timings_;
};

}  // namespace

const MpiTransport& Mpi() {
  if (!g_mpi) throw std::logic_error("MPI used in a process mpirun did not launch");
  return *g_mpi;
}

void MpiInitIfLaunched(int* argc, char*** argv) {
  // Launched by mpirun (OpenMPI, or a PMI-based launcher): load the MPI module and join the
  // job. A plain run never loads MPI, so it needs no launcher and behaves exactly as a build
  // without MPI.
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE") &&
      !std::getenv("PMIX_RANK")) {
    return;
  }
  if (!MpiBuiltIn()) {
    throw InputError(
        "launched by mpirun, but this hexgait was built without MPI (Debian: "
        "libopenmpi-dev, then rebuild)");
  }
  std::string error;
  const SharedLibrary* module = SharedLibrary::OpenModule(HEXGAIT_MPI_MODULE_FILE, &error);
  const MpiTransport* (*get)() = nullptr;
  if (!module || !module->Bind(HEXGAIT_MPI_TRANSPORT_SYMBOL, get, &error)) {
    throw InputError("launched by mpirun, but the MPI module cannot be loaded: " + error);
  }
  const MpiTransport* transport = get();
  if (transport->version != kMpiTransportVersion) {
    throw InputError("launched by mpirun, but " + module->name() + " is from another build");
  }
  if (transport->init(argc, argv) != 0) throw InputError("MPI_Init_thread failed");
  g_mpi = transport;
  if (MpiIsWorker()) {
    std::fflush(stdout);
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) {
      throw std::runtime_error("a worker rank cannot redirect its output to /dev/null");
    }
  }
}

void MpiFinalize() {
  if (g_mpi) g_mpi->finalize();
  g_mpi = nullptr;
}

void MpiAbort(int code) {
  if (g_mpi) g_mpi->abort(code);
}

int MpiWorldSize() {
  return g_mpi ? g_mpi->world_size() : 1;
}

int MpiRank() {
  return g_mpi ? g_mpi->rank() : 0;
}

bool MpiIsWorker() {
  return MpiRank() > 0;
}

namespace {

// A worker rank's side of MpiEvaluator: until rank 0's evaluator is destroyed.
void ServeMpiEvaluations(const CreatureModel& model, const MotorProgram& program,
                         const EvaluatorConfig& config) {
  const auto local = MakeLocalEvaluator(model, program, WholeBatches(config));
  for (;;) {
    Header h;
    WaitForMessage(0, kTagHeader);
    Mpi().receive(&h, 3, kMpiLongLong, 0, kTagHeader);
    if (h.count < 0) return;
    if (h.count == 0) continue;
    std::vector<double> flat(static_cast<size_t>(h.count * h.springs * h.positions));
    Mpi().receive(flat.data(), static_cast<int>(flat.size()), kMpiDouble, 0, kTagTables);
    std::vector<RestLengthTable> tables(static_cast<size_t>(h.count));
    const size_t cells = static_cast<size_t>(h.springs * h.positions);
    for (size_t k = 0; k < tables.size(); ++k) {
      tables[k].num_springs = static_cast<int>(h.springs);
      tables[k].num_positions = static_cast<int>(h.positions);
      tables[k].length.assign(flat.begin() + k * cells, flat.begin() + (k + 1) * cells);
    }
    // Results, then this rank's evaluation time (for `bench scale`).
    std::vector<char> out(1, 0);
    try {
      const auto start = Clock::now();
      for (const RunResult& r : local->Evaluate(tables)) PutResult(out, r);
      Put(out, SecondsSince(start));
    } catch (const std::exception& e) {
      out.assign(1, 1);
      out.insert(out.end(), e.what(), e.what() + std::strlen(e.what()));
    }
    Mpi().send(out.data(), static_cast<int>(out.size()), kMpiBytes, 0, kTagResults);
  }
}

}  // namespace

std::unique_ptr<Evaluator> MakeMpiEvaluator(const CreatureModel& model, const MotorProgram& program,
                                            const EvaluatorConfig& config, MpiTimings* timings) {
  if (MpiIsWorker()) {
    ServeMpiEvaluations(model, program, config);
    throw MpiWorkerDone{};
  }
  return std::make_unique<MpiEvaluator>(model, program, config, timings);
}

}  // namespace hexgait
