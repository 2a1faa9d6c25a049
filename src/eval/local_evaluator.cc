// The local backend: batches of tables over this process's threads, each batch in SIMD lanes,
// on the creature kernel, or one by one on the scalar path (what the GA's EvaluateInParallel
// did before the seam, unchanged in every bit).
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "eval/evaluator.h"
#include "sim/batch_evaluate.h"
#include "sim/creature_simulation.h"
#include "sim/evaluate.h"
#include "sim/lane_refill.h"
#include "util/clock.h"

namespace hexgait {
namespace {

class LocalEvaluator final : public Evaluator {
 public:
  LocalEvaluator(const CreatureModel& model, const MotorProgram& program,
                 const EvaluatorConfig& config)
      : model_(model), program_(program), config_(config) {}

  std::vector<RunResult> Evaluate(std::span<const RestLengthTable> tables,
                                  const Progress& on_progress) override {
    return Run(tables, on_progress, nullptr);
  }
  std::vector<RunResult> EvaluateWithFollowUps(std::span<const RestLengthTable> tables,
                                               FollowUps& follow_ups,
                                               const Progress& on_progress) override {
    follow_ups.in_double.assign(tables.size(), RunResult{});
    follow_ups.ran.assign(tables.size(), 0);
    return Run(tables, on_progress, &follow_ups);
  }

  std::string Describe() const override {
    return "local, " + std::to_string(ResolveThreadCount(config_.threads)) + " threads";
  }

 private:
  // `follow_ups`: null, or the tables to run again in double, overlapped with the float lanes
  // where the run refills them (else none are run here).
  std::vector<RunResult> Run(std::span<const RestLengthTable> tables, const Progress& on_progress,
                             FollowUps* follow_ups);

  const CreatureModel& model_;
  const MotorProgram& program_;
  EvaluatorConfig config_;
};

std::vector<RunResult> LocalEvaluator::Run(std::span<const RestLengthTable> tables,
                                           const Progress& on_progress, FollowUps* follow_ups) {
  const RunOptions& options = config_.run;
  const int total = static_cast<int>(tables.size());
  std::vector<RunResult> results(tables.size());
  const int workers_wanted = ResolveThreadCount(config_.threads);
  // Batches of consecutive tables; the scalar path for what the batched kernels do not model
  // (other integrators, a slope, a push), and for double with --batch-lanes 1. Float always
  // runs batched (it has no scalar path: one lane of the batched kernel), which refuses those.
  const bool batchable = BatchedPathAccepts(model_, options);
  const bool batched =
      config_.precision == Precision::kFloat || (batchable && config_.batch_lanes != 1);
  const std::vector<int> sizes =
      batched ? PlanBatches(total, workers_wanted, config_.batch_lanes, config_.precision,
                            CreatureSimulation::Available(model_))
              : std::vector<int>(total, 1);
  std::vector<int> first(sizes.size() + 1, 0);
  for (size_t b = 0; b < sizes.size(); ++b) first[b + 1] = first[b] + sizes[b];
  // Runs that can end early (a fall under stop_at_fall, rest under early_stop) refill their
  // lanes: each thread runs one stream of lanes, and a lane whose creature is done takes the
  // next table at once (sim/lane_refill.h; the same bits). The creature kernel keeps its
  // batches of a few creatures.
  const bool refill = config_.refill_lanes && batched && batchable && !sizes.empty() &&
                      (options.stop_at_fall || options.early_stop) &&
                      !RunsOnCreatureKernel(model_, sizes.front(), config_.batch_lanes,
                                            BatchIsa::kAuto, config_.precision);
  const int num_batches = refill ? std::min(workers_wanted, static_cast<int>(sizes.size()))
                                 : static_cast<int>(sizes.size());
  const int refill_lanes = refill ? BatchLanesFor(sizes.front()) : 0;
  std::atomic<int> next_table{0};

  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  std::atomic<bool> stopped{false};
  // The longest time between stop polls, for the stop acknowledgement's "within about N s".
  std::atomic<long long> longest_batch_us{0};
  std::mutex progress_mutex;
  std::condition_variable progress;
  int workers_done = 0;  // guarded by progress_mutex
  // A stop poll for one thread, called between chunks of simulation (a check interval, or a
  // whole scalar run): it notes the longest time between polls, which is the stop's latency
  // that the acknowledgement quotes, and is true once a stop was asked for or a thread failed.
  auto make_stop_poll = [&] {
    return [&, last = Clock::now()]() mutable {
      const auto now = Clock::now();
      const long long us =
          std::chrono::duration_cast<std::chrono::microseconds>(now - last).count();
      last = now;
      long long seen = longest_batch_us.load();
      while (us > seen && !longest_batch_us.compare_exchange_weak(seen, us)) {
      }
      NoteSafePointInterval(static_cast<double>(std::max(us, seen)) * 1e-6);
      return (config_.stop_on_request && StopRequested()) || failed.load();
    };
  };
  // Follow-ups (float lanes only): a table whose first result calls for it joins a queue the
  // moment that result is final, and every thread's double lanes take from it between chunks
  // of their float lanes. Which thread runs which changes no result.
  const bool follow = follow_ups && refill && config_.precision == Precision::kFloat;
  std::mutex queue_mutex;
  std::condition_variable queue_changed;
  std::vector<int> queue;  // guarded by queue_mutex, as is the end of the first runs below
  bool first_runs_over = false;
  auto end_follow_ups = [&] {
    std::lock_guard<std::mutex> lock(queue_mutex);
    first_runs_over = true;
    queue_changed.notify_all();
  };
  // One thread's stream of refilled lanes; false when a stop ended it.
  auto stream = [&] {
    RefillStream s;
    s.claim = [&] {
      const int i = next_table.fetch_add(1);
      return i < total && !failed.load() ? i : -1;
    };
    s.finished = [&](int i) {
      if (follow && follow_ups->wanted(results[static_cast<size_t>(i)])) {
        std::lock_guard<std::mutex> lock(queue_mutex);
        queue.push_back(i);
        queue_changed.notify_one();
      }
      if (done.fetch_add(1) + 1 == total && follow) end_follow_ups();
    };
    s.stop = make_stop_poll();
    if (!follow) {
      return EvaluateRefilled(model_, program_, tables, options, refill_lanes, results, s,
                              BatchIsa::kAuto, config_.precision);
    }
    // A thread takes follow-ups a whole vector of double lanes at a time (or what is left once
    // every first result is in): a confirmation runs the whole test, so lanes started one by one
    // would step mostly empty.
    const int follow_lanes = NativeBatchLanes(BatchIsa::kAuto, Precision::kDouble);
    RefillStream f;
    f.claim = [&, group = 0]() mutable {
      std::lock_guard<std::mutex> lock(queue_mutex);
      if (group == 0 && (static_cast<int>(queue.size()) >= follow_lanes || first_runs_over)) {
        group = follow_lanes;
      }
      if (queue.empty() || group == 0) {
        group = 0;
        return first_runs_over || failed.load() ? -1 : RefillStream::kLater;
      }
      --group;
      const int i = queue.back();
      queue.pop_back();
      follow_ups->ran[static_cast<size_t>(i)] = 1;
      return i;
    };
    f.wait = [&] {
      std::unique_lock<std::mutex> lock(queue_mutex);
      queue_changed.wait(lock, [&] { return !queue.empty() || first_runs_over || failed.load(); });
    };
    const bool whole =
        EvaluateRefilledWithFollowUps(model_, program_, tables, options, refill_lanes, results, s,
                                      follow_lanes, follow_ups->in_double, f, config_.precision);
    if (!whole) end_follow_ups();  // a stopped thread's children never finish: wake the others
    return whole;
  };
  auto work = [&] {
    if (refill) {
      if (next.fetch_add(1) >= num_batches) return;
      try {
        if (!stream() && !failed.load()) stopped.store(true);
      } catch (...) {
        if (!failed.exchange(true)) error = std::current_exception();
        if (follow) end_follow_ups();  // no thread may wait for follow-ups this one owed
      }
      return;
    }
    const std::function<bool()> stop_poll = make_stop_poll();
    for (int b; (b = next.fetch_add(1)) < num_batches && !failed.load();) {
      // One atomic load per check interval, never per step: the step loop stays free of it.
      if (stop_poll()) {
        stopped.store(true);
        return;
      }
      try {
        const auto batch = tables.subspan(first[b], sizes[b]);
        if (batched) {
          const std::vector<RunResult> out = EvaluateBatched(
              model_, program_, batch, options, 0, BatchIsa::kAuto, config_.precision, stop_poll);
          if (out.empty()) {  // stopped within the batch
            stopped.store(true);
            return;
          }
          std::copy(out.begin(), out.end(), results.begin() + first[b]);
        } else {
          results[first[b]] = EvaluateRestLengths(model_, program_, batch.front(), options);
        }
      } catch (...) {
        if (!failed.exchange(true)) error = std::current_exception();
      }
      done.fetch_add(sizes[b]);
    }
  };
  const int workers = std::max(1, std::min(workers_wanted, num_batches));
  if (workers == 1) {
    work();
  } else {
    // Every worker evaluates; the calling thread only reports progress, every 100 ms, and
    // returns as soon as the last worker is done. (It used to evaluate too, after reporting
    // until every batch was claimed: with as many batches as threads, that ran them one after
    // the other.)
    std::vector<std::thread> pool;
    for (int t = 0; t < workers; ++t) {
      pool.emplace_back([&] {
        work();
        std::lock_guard<std::mutex> lock(progress_mutex);
        ++workers_done;
        progress.notify_one();
      });
    }
    {
      std::unique_lock<std::mutex> lock(progress_mutex);
      while (workers_done < workers) {
        if (on_progress) {
          lock.unlock();
          on_progress("evaluations", done.load(), total);
          lock.lock();
        }
        progress.wait_for(lock, std::chrono::milliseconds(100),
                          [&] { return workers_done == workers; });
      }
    }
    for (std::thread& t : pool) t.join();
  }
  if (error) std::rethrow_exception(error);
  if (stopped.load()) throw EvaluationStopped(done.load(), total);
  if (on_progress) on_progress("evaluations", total, total);
  return results;
}

}  // namespace

std::unique_ptr<Evaluator> MakeLocalEvaluator(const CreatureModel& model,
                                              const MotorProgram& program,
                                              const EvaluatorConfig& config) {
  return std::make_unique<LocalEvaluator>(model, program, config);
}

int ResolveThreadCount(int requested) {
  if (requested > 0) return requested;
  // The CPUs this process may run on, as `nproc` counts them: fewer than the machine's under
  // taskset, a container's CPU set or an MPI launcher's binding (results never depend on it).
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0) {
    return CPU_COUNT(&allowed);
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

std::vector<int> PlanBatches(int pending, int threads, int batch_lanes, Precision precision,
                             bool creature_kernel) {
  if (pending <= 0) return {};
  int lanes = batch_lanes;
  const int per_thread = (pending + threads - 1) / std::max(1, threads);
  if (lanes <= 0 && creature_kernel && precision == Precision::kFloat &&
      per_thread <= kCreatureKernelMaxBatch) {
    lanes = per_thread;
  } else if (lanes <= 0) {
    // Fill vector registers before spreading over threads: a batch narrower than the vector
    // costs about as much per step as a full one (`hexgait bench speed`, lanes rows), so
    // splitting the paper's 3 creatures 2 + 1 over two threads saves little and doubles the
    // CPU time. No wider than the instruction set runs at its best per creature.
    lanes = std::min(PreferredBatchLanes(BatchIsa::kAuto, precision),
                     std::max(NativeBatchLanes(BatchIsa::kAuto, precision), per_thread));
  }
  lanes = std::min(lanes, kMaxBatchLanes);
  const int batches = (pending + lanes - 1) / lanes;
  std::vector<int> sizes(batches, pending / batches);
  for (int b = 0; b < pending % batches; ++b) ++sizes[b];
  return sizes;
}

}  // namespace hexgait
