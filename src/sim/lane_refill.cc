#include "sim/lane_refill.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "motor/lane_clocked_controller.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_state.h"
#include "sim/evaluate.h"
#include "sim/lane_measures.h"
#include "util/error.h"

namespace hexgait {
namespace {

// RefilledLaneSteps' totals: [0] double lanes, [1] float lanes.
std::atomic<long long> g_stepped[2], g_running[2];

template <class T>
class RefillRun {
 public:
  RefillRun(const CreatureModel& model, const MotorProgram& program,
            std::span<const RestLengthTable> tables, const RunOptions& options, int lanes,
            std::span<RunResult> results, const RefillStream& stream, BatchIsa isa)
      : model_(model),
        tables_(tables),
        options_(options),
        results_(results),
        stream_(stream),
        rest_(MakeRestState(model)),
        lane_state_(MakeRestState(model)),
        controller_(model, program, lanes, options.dt),
        state_(MakeBatchStateT<T>(model, rest_, lanes)),
        args_(MakeBatchKernelArgs(model, state_, options.dt)),
        step_fn_(SelectBatchStepT<T>(lanes, isa)),
        isa_(isa),
        total_(std::llround(options.duration / options.dt)),
        lane_(static_cast<size_t>(lanes)),
        body_(static_cast<size_t>(lanes)),
        in_bounds_(static_cast<size_t>(lanes)) {
    // The start as the lanes hold it (rounded to T), as EvaluateBatched measures it.
    ExtractLane(state_, 0, lane_state_);
    start_x_ = BodyCentre(model, lane_state_).x();
  }
  ~RefillRun() {
    constexpr int kind = std::is_same_v<T, float> ? 1 : 0;
    g_stepped[kind].fetch_add(lane_steps_.stepped, std::memory_order_relaxed);
    g_running[kind].fetch_add(lane_steps_.running, std::memory_order_relaxed);
  }
  RefillRun(const RefillRun&) = delete;
  RefillRun& operator=(const RefillRun&) = delete;

  // Every lane's first table, then chunks until no lane runs; false when `stop` ended it.
  bool Run() {
    Begin();
    while (running_ > 0) {
      Advance();
      if (stream_.stop && stream_.stop()) return false;
    }
    return true;
  }

  // Gives every lane its first table.
  void Begin() {
    for (int l = 0; l < static_cast<int>(lane_.size()); ++l) Fill(l);
  }
  // Gives a table to each lane that waits for one (its stream said kLater), until the stream
  // says kLater again.
  void Refill() {
    for (int l = 0; l < static_cast<int>(lane_.size()); ++l) {
      const Lane& lane = lane_[static_cast<size_t>(l)];
      if (lane.index >= 0 || lane.closed) continue;
      Fill(l);
      if (lane.index < 0 && !lane.closed) return;
    }
  }
  // Whether a lane runs a creature, or may get one.
  bool open() const {
    for (const Lane& lane : lane_) {
      if (lane.index >= 0 || !lane.closed) return true;
    }
    return false;
  }
  int running() const { return running_; }

  // Steps every lane to the nearest event of a running lane (its next check, or the end of its
  // time), then checks the lanes there; nothing when no lane runs.
  void Advance() {
    if (running_ == 0) return;
    const long long interval = options_.check_interval;
    long long chunk = interval;
    for (const Lane& lane : lane_) {
      if (lane.index < 0) continue;
      const long long local = state_.step - lane.offset;
      const long long next = std::min(total_, (local / interval + 1) * interval);
      chunk = std::min(chunk, next - local);
    }
    lane_steps_.stepped += chunk * static_cast<long long>(lane_.size());
    lane_steps_.running += chunk * running_;
    for (long long k = 0; k < chunk; ++k) {
      controller_.Update(state_.step, state_.rest_length.data());
      step_fn_(args_);
      ++state_.step;
    }
    // Lanes that start at a check stay in step (a run ends at a check or at the end of its
    // time, both multiples of the interval), so most chunks end at every running lane's check:
    // then all lanes are measured at once.
    int due = 0;
    for (const Lane& lane : lane_) {
      due += lane.index >= 0 && (state_.step - lane.offset) % interval == 0;
    }
    measured_all_ = due > 1 && !options_.early_stop;
    if (measured_all_) {
      MeasureLanes(model_, state_, options_.divergence_speed, 0, static_cast<int>(lane_.size()),
                   body_, in_bounds_, isa_);
    }
    for (int l = 0; l < static_cast<int>(lane_.size()); ++l) {
      if (lane_[static_cast<size_t>(l)].index >= 0) CheckLane(l);
    }
  }

 private:
  struct Lane {
    int index = -1;       // the table this lane runs; -1: none
    bool closed = false;  // its stream has no table left for it
    long long offset = 0;
    std::optional<RunMonitor> monitor;
  };

  // Gives lane `l` the next table, starting now; creatures of no steps finish at once.
  void Fill(int l) {
    Lane& lane = lane_[static_cast<size_t>(l)];
    for (;;) {
      const int claimed = stream_.claim();
      lane.index = claimed < 0 ? -1 : claimed;
      if (claimed < 0) {
        controller_.StopLane(l);
        lane.closed = claimed != RefillStream::kLater;
        return;
      }
      RunResult& r = results_[static_cast<size_t>(lane.index)];
      r = RunResult{};
      r.min_body_height = INFINITY;
      lane.monitor.emplace(model_, controller_.cycle_period(), options_, r);
      lane.offset = state_.step;
      InsertLane(rest_, l, state_);
      controller_.StartLane(l, tables_[static_cast<size_t>(lane.index)], state_.step,
                            state_.rest_length.data());
      ++running_;
      if (total_ > 0) return;
      ExtractAt(l, 0);
      lane.monitor->Check(lane_state_);  // as the loop's check after no steps
      Finish(l, 0);
    }
  }

  // Measures lane `l` unless this chunk measured every lane; whether it is in bounds (and
  // body_[l] holds its measures).
  bool Measure(int l) {
    if (!measured_all_) {
      MeasureLanes(model_, state_, options_.divergence_speed, l, 1, body_, in_bounds_, isa_);
    }
    return in_bounds_[static_cast<size_t>(l)] != 0;
  }

  void ExtractAt(int l, long long local) {
    ExtractLane(state_, l, lane_state_);
    lane_state_.step = local;
    lane_state_.time = static_cast<double>(local) * options_.dt;
  }

  // At lane `l`'s check or end: the scalar RunLoop's checks, in its order.
  void CheckLane(int l) {
    Lane& lane = lane_[static_cast<size_t>(l)];
    const long long local = state_.step - lane.offset;
    const bool at_check = local % options_.check_interval == 0;
    const bool at_end = local == total_;
    if (!at_check && !at_end) return;
    RunMonitor& monitor = *lane.monitor;
    const RunResult& r = results_[static_cast<size_t>(lane.index)];
    // The lane is measured where it stays in bounds (sim/lane_measures.h), and copied out for
    // what needs its whole state: a divergence's message, early_stop, the end of its run.
    bool extracted = false;
    auto extract = [&] {
      if (!extracted) ExtractAt(l, local);
      extracted = true;
    };
    if (at_check) {
      bool goes_on;
      if (!options_.early_stop && Measure(l)) {
        goes_on = monitor.CheckMeasured(body_[l], static_cast<double>(local) * options_.dt);
      } else {
        extract();
        goes_on = monitor.Check(lane_state_);
      }
      if (goes_on && !at_end) return;
      extract();
      // RunLoop's check after its loop: after the last check, or after a stop other than a
      // divergence.
      if (goes_on || !r.diverged) monitor.Check(lane_state_);
    } else {
      extract();
      monitor.Check(lane_state_);  // the last, shorter chunk: only the check after the loop
    }
    Finish(l, local);
    Fill(l);
  }

  void Finish(int l, long long local) {
    Lane& lane = lane_[static_cast<size_t>(l)];
    RunResult& r = results_[static_cast<size_t>(lane.index)];
    r.steps = local;
    r.end_time = static_cast<double>(local) * options_.dt;
    r.distance = r.diverged ? 0.0 : BodyCentre(model_, lane_state_).x() - start_x_;
    lane.monitor.reset();
    --running_;
    if (stream_.finished) stream_.finished(lane.index);
    lane.index = -1;
  }

  const CreatureModel& model_;
  std::span<const RestLengthTable> tables_;
  const RunOptions& options_;
  std::span<RunResult> results_;
  const RefillStream& stream_;
  SimState rest_, lane_state_;
  LaneClockedController controller_;
  BatchStateT<T> state_;
  BatchKernelArgsT<T> args_;
  BatchStepFnT<T> step_fn_;
  BatchIsa isa_;
  long long total_;
  std::vector<Lane> lane_;
  std::vector<BodyMeasures> body_;  // per lane, where Measure has measured it
  std::vector<char> in_bounds_;
  bool measured_all_ = false;  // this chunk's end measured every lane
  double start_x_ = 0;
  int running_ = 0;
  LaneSteps lane_steps_;  // this run's, added to the process's totals at its end
};

void RequireRefillable(const CreatureModel& model, const RunOptions& options,
                       std::span<const RestLengthTable> tables, std::span<RunResult> results) {
  if (const char* why = BatchedPathRefusal(model, options)) {
    throw InputError(std::string("the batched simulator ") + why);
  }
  if (results.size() != tables.size()) throw InputError("one result per table is needed");
}

// Two runs on one thread, a chunk of each in turn; the second waits for follow-ups when
// neither has a creature to step. The first stream's stop poll serves both.
template <class First>
bool RunWithFollowUps(First& first, RefillRun<double>& second, const RefillStream& stream,
                      const RefillStream& follow_ups) {
  first.Begin();
  second.Begin();
  for (;;) {
    first.Advance();
    second.Refill();
    second.Advance();
    if (stream.stop && stream.stop()) return false;
    if (first.running() > 0 || second.running() > 0) continue;
    if (!second.open()) return true;
    follow_ups.wait();
    second.Refill();
  }
}

}  // namespace

bool EvaluateRefilledWithFollowUps(const CreatureModel& model, const MotorProgram& program,
                                   std::span<const RestLengthTable> tables,
                                   const RunOptions& options, int lanes,
                                   std::span<RunResult> results, const RefillStream& stream,
                                   int follow_up_lanes, std::span<RunResult> follow_up_results,
                                   const RefillStream& follow_ups, Precision precision) {
  RequireRefillable(model, options, tables, results);
  RequireRefillable(model, options, tables, follow_up_results);
  if (!follow_ups.wait) throw InputError("a follow-up stream needs a wait");
  RefillRun<double> second(model, program, tables, options, follow_up_lanes, follow_up_results,
                           follow_ups, BatchIsa::kAuto);
  if (precision == Precision::kFloat) {
    RefillRun<float> first(model, program, tables, options, lanes, results, stream,
                           BatchIsa::kAuto);
    return RunWithFollowUps(first, second, stream, follow_ups);
  }
  RefillRun<double> first(model, program, tables, options, lanes, results, stream, BatchIsa::kAuto);
  return RunWithFollowUps(first, second, stream, follow_ups);
}

LaneSteps RefilledLaneSteps(Precision precision) {
  const int kind = precision == Precision::kFloat ? 1 : 0;
  return {g_stepped[kind].load(std::memory_order_relaxed),
          g_running[kind].load(std::memory_order_relaxed)};
}

bool EvaluateRefilled(const CreatureModel& model, const MotorProgram& program,
                      std::span<const RestLengthTable> tables, const RunOptions& options, int lanes,
                      std::span<RunResult> results, const RefillStream& stream, BatchIsa isa,
                      Precision precision) {
  RequireRefillable(model, options, tables, results);
  if (precision == Precision::kFloat) {
    return RefillRun<float>(model, program, tables, options, lanes, results, stream, isa).Run();
  }
  return RefillRun<double>(model, program, tables, options, lanes, results, stream, isa).Run();
}

}  // namespace hexgait
