#include "sim/batch_evaluate.h"

#include <cmath>
#include <string>

#include "motor/batch_controller.h"
#include "motor/leg_targets.h"
#include "sim/batch_state.h"
#include "util/error.h"

namespace hexgait {

std::vector<RunResult> EvaluateGenomesBatched(const CreatureModel& model,
                                              const MotorProgram& program,
                                              const std::vector<const Genome*>& genomes,
                                              const RunOptions& options, int lanes, BatchIsa isa) {
  const int count = static_cast<int>(genomes.size());
  if (count == 0) return {};
  if (lanes == 0) lanes = BatchLanesFor(count);
  if (count > lanes) {
    std::string message = "a batch of ";
    message += std::to_string(count);
    message += " genomes does not fit in ";
    message += std::to_string(lanes);
    message += " lanes";
    throw InputError(message);
  }
  if (options.integrator != IntegratorKind::kEuler) {
    throw InputError("the batched simulator runs the explicit Euler integrator only");
  }
  const BatchStepFn step_fn = SelectBatchStep(lanes, isa);

  std::vector<RestLengthTable> tables;
  for (const Genome* genome : genomes) {
    tables.push_back(PerturbedRestLengths(model, program, *genome));
  }
  while (static_cast<int>(tables.size()) < lanes) tables.push_back(tables.front());
  BatchMotorController controller(model, program, std::move(tables), options.dt);

  SimState lane_state = MakeRestState(model);  // scratch: one lane, for the monitors
  BatchState state = MakeBatchState(model, lane_state, lanes);
  const BatchKernelArgs args = MakeBatchKernelArgs(model, state, options.dt);

  std::vector<RunResult> results(count);
  std::vector<RunMonitor> monitors;
  std::vector<char> running(count, 1);
  for (RunResult& r : results) {
    r.min_body_height = INFINITY;
    monitors.emplace_back(model, controller.cycle_period(), options, r);
  }
  const double start_x = BodyCentre(model, lane_state).x();
  int num_running = count;

  // The scalar RunLoop, step for step; lanes only diverge in which of them still count.
  const long long total = static_cast<long long>(std::llround(options.duration / options.dt));
  int until_check = options.check_interval;
  for (long long k = 0; k < total && num_running > 0; ++k) {
    controller.Update(k, state.rest_length.data());
    step_fn(args);
    ++state.step;
    state.time = static_cast<double>(state.step) * options.dt;
    if (--until_check == 0) {
      until_check = options.check_interval;
      for (int lane = 0; lane < count; ++lane) {
        if (!running[lane]) continue;
        ExtractLane(state, lane, lane_state);
        if (monitors[lane].Check(lane_state)) continue;
        // Diverged or at rest: freeze the result where the scalar loop stops.
        running[lane] = 0;
        --num_running;
        RunResult& r = results[lane];
        if (!r.diverged) monitors[lane].Check(lane_state);  // as RunLoop's check after its loop
        r.steps = state.step;
        r.end_time = state.time;
        r.distance = r.diverged ? 0.0 : BodyCentre(model, lane_state).x() - start_x;
      }
    }
  }
  for (int lane = 0; lane < count; ++lane) {
    if (!running[lane]) continue;
    ExtractLane(state, lane, lane_state);
    monitors[lane].Check(lane_state);
    RunResult& r = results[lane];
    r.steps = state.step;
    r.end_time = state.time;
    r.distance = r.diverged ? 0.0 : BodyCentre(model, lane_state).x() - start_x;
  }
  return results;
}

}  // namespace hexgait
