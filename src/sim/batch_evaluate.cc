#include "sim/batch_evaluate.h"

#include <cmath>
#include <functional>
#include <string>

#include "motor/leg_targets.h"
#include "util/error.h"

namespace hexgait {

namespace {

std::vector<RestLengthTable> LaneTables(std::span<const RestLengthTable> given, int lanes) {
  std::vector<RestLengthTable> tables(given.begin(), given.end());
  while (static_cast<int>(tables.size()) < lanes) tables.push_back(tables.front());
  return tables;
}

void RequireBatchableRun(const CreatureModel& model, const RunOptions& options,
                         const char* simulator) {
  if (const char* why = BatchedPathRefusal(model, options)) {
    throw InputError(std::string(simulator) + " " + why);
  }
}

int CheckedLanes(int count, int lanes) {
  if (count == 0) throw InputError("a batch needs at least one rest-length table");
  if (lanes == 0) lanes = BatchLanesFor(count);
  if (count > lanes) {
    std::string message = "a batch of ";
    message += std::to_string(count);
    message += " creatures does not fit in ";
    message += std::to_string(lanes);
    message += " lanes";
    throw InputError(message);
  }
  return lanes;
}

// The scalar RunLoop, step for step; lanes only diverge in which of them still count. Sim:
// BatchSimulation<T> or CreatureSimulation.
// An empty result when `stop` (polled between chunks) asked to abandon the runs.
template <class Sim>
std::vector<RunResult> Evaluate(const CreatureModel& model, Sim& sim, int count,
                                const RunOptions& options, const std::function<bool()>& stop) {
  SimState lane_state = MakeRestState(model);  // scratch: one lane, for the monitors
  std::vector<RunResult> results(count);
  std::vector<RunMonitor> monitors;
  std::vector<char> running(count, 1);
  for (RunResult& r : results) {
    r.min_body_height = INFINITY;
    monitors.emplace_back(model, sim.cycle_period(), options, r);
  }
  // The start as the lanes hold it (rounded to T).
  sim.Extract(0, lane_state);
  const double start_x = BodyCentre(model, lane_state).x();
  int num_running = count;

  // Lanes are measured all at once where the simulation can (BatchSimulation), and a lane is
  // copied out only for what needs its whole state: a divergence's message, early_stop's rest
  // test, the end of its run.
  constexpr bool kMeasuresLanes = requires(std::span<BodyMeasures> b, std::span<char> c) {
    sim.Measure(model, 0.0, b, c);
  };
  const bool measure = kMeasuresLanes && !options.early_stop;
  std::vector<BodyMeasures> body;
  std::vector<char> in_bounds;
  if constexpr (kMeasuresLanes) {
    body.resize(static_cast<size_t>(sim.lanes()));
    in_bounds.resize(body.size());
  }

  const long long total = static_cast<long long>(std::llround(options.duration / options.dt));
  const long long interval = options.check_interval;
  while (sim.step() < total && num_running > 0) {
    // Monitors run every check_interval steps, as in RunLoop; the last chunk may be shorter.
    const long long chunk = std::min(interval, total - sim.step());
    sim.Advance(chunk);
    if (stop && stop()) return {};
    if (chunk < interval) break;
    if constexpr (kMeasuresLanes) {
      if (measure) sim.Measure(model, options.divergence_speed, body, in_bounds);
    }
    for (int lane = 0; lane < count; ++lane) {
      if (!running[lane]) continue;
      bool goes_on;
      if (measure && in_bounds[lane]) {
        goes_on = monitors[lane].CheckMeasured(body[lane], sim.time());
      } else {
        sim.Extract(lane, lane_state);
        goes_on = monitors[lane].Check(lane_state);
      }
      if (goes_on) continue;
      sim.Extract(lane, lane_state);
      // Diverged or at rest: freeze the result where the scalar loop stops.
      running[lane] = 0;
      --num_running;
      RunResult& r = results[lane];
      if (!r.diverged) monitors[lane].Check(lane_state);  // as RunLoop's check after its loop
      r.steps = sim.step();
      r.end_time = sim.time();
      r.distance = r.diverged ? 0.0 : BodyCentre(model, lane_state).x() - start_x;
    }
  }
  for (int lane = 0; lane < count; ++lane) {
    if (!running[lane]) continue;
    sim.Extract(lane, lane_state);
    monitors[lane].Check(lane_state);
    RunResult& r = results[lane];
    r.steps = sim.step();
    r.end_time = sim.time();
    r.distance = r.diverged ? 0.0 : BodyCentre(model, lane_state).x() - start_x;
  }
  return results;
}

}  // namespace

const char* BatchedPathRefusal(const CreatureModel& model, const RunOptions& options) {
  if (options.integrator != IntegratorKind::kEuler)
    return "runs the explicit Euler integrator only";
  if (model.physics.gravity_x != 0) return "models flat ground only (gravity along -z)";
  if (options.push_impulse != 0) return "does not push";
  return nullptr;
}

bool RunsOnCreatureKernel(const CreatureModel& model, int count, int lanes, BatchIsa isa,
                          Precision precision) {
  return precision == Precision::kFloat && lanes == 0 &&
         (isa == BatchIsa::kAuto || isa == BatchIsa::kAvx512) && count <= kCreatureKernelMaxBatch &&
         CreatureSimulation::Available(model);
}

template <class T>
BatchSimulation<T>::BatchSimulation(const CreatureModel& model, const MotorProgram& program,
                                    std::span<const RestLengthTable> tables, double dt, int lanes,
                                    BatchIsa isa)
    : dt_(dt),
      isa_(isa),
      controller_(model, program,
                  LaneTables(tables, CheckedLanes(static_cast<int>(tables.size()), lanes)), dt),
      state_(MakeBatchStateT<T>(model, MakeRestState(model), controller_.lanes())),
      args_(MakeBatchKernelArgs(model, state_, dt)),
      step_fn_(SelectBatchStepT<T>(controller_.lanes(), isa)) {}

template class BatchSimulation<double>;
template class BatchSimulation<float>;

std::vector<RunResult> EvaluateBatched(const CreatureModel& model, const MotorProgram& program,
                                       std::span<const RestLengthTable> tables,
                                       const RunOptions& options, int lanes, BatchIsa isa,
                                       Precision precision, const std::function<bool()>& stop) {
  if (tables.empty()) return {};
  RequireBatchableRun(model, options, "the batched simulator");
  const int count = static_cast<int>(tables.size());
  if (RunsOnCreatureKernel(model, count, lanes, isa, precision)) {
    CreatureSimulation sim(model, program, tables, options.dt);
    return Evaluate(model, sim, count, options, stop);
  }
  if (precision == Precision::kFloat) {
    BatchSimulation<float> sim(model, program, tables, options.dt, lanes, isa);
    return Evaluate(model, sim, count, options, stop);
  }
  BatchSimulation<double> sim(model, program, tables, options.dt, lanes, isa);
  return Evaluate(model, sim, count, options, stop);
}

std::vector<RunResult> EvaluateWithCreatureKernel(const CreatureModel& model,
                                                  const MotorProgram& program,
                                                  std::span<const RestLengthTable> tables,
                                                  const RunOptions& options) {
  if (tables.empty()) return {};
  RequireBatchableRun(model, options, "the creature kernel");
  CreatureSimulation sim(model, program, tables, options.dt);
  return Evaluate(model, sim, static_cast<int>(tables.size()), options, {});
}

}  // namespace hexgait
