// Backend registration: the one place that decides which Evaluator a process gets; and the
// check of the settings every backend takes.
#include "eval/evaluator.h"

#include <algorithm>
#include <chrono>

#include "eval/mpi_evaluator.h"
#include "util/clock.h"
#include "util/error.h"

namespace hexgait {

EvaluationStopped::EvaluationStopped(int done_count, int total_count)
    : Stopped("the population under way was dropped (" + std::to_string(done_count) + " of " +
              std::to_string(total_count) + " simulations run)"),
      done(done_count),
      total(total_count) {}

void CheckEvaluatorConfig(const EvaluatorConfig& config) {
  if (config.threads < 0 || config.threads > 1024) {
    throw InputError("--threads must be in [0, 1024]");
  }
  if (config.batch_lanes < 0 || config.batch_lanes > kMaxBatchLanes) {
    throw InputError("--batch-lanes must be in [0, " + std::to_string(kMaxBatchLanes) + "]");
  }
  if (config.precision == Precision::kFloat && config.run.integrator != IntegratorKind::kEuler) {
    throw InputError("--precision float needs --integrator euler");
  }
}

std::vector<RunResult> EvaluateInSlices(Evaluator& evaluator,
                                        std::span<const RestLengthTable> tables, int threads,
                                        double slice_seconds, const Progress& between) {
  std::vector<RunResult> results;
  results.reserve(tables.size());
  const size_t unit = static_cast<size_t>(ResolveThreadCount(threads)) * 16;
  size_t slice = unit;
  for (size_t start = 0; start < tables.size();) {
    const size_t count = std::min(slice, tables.size() - start);
    const auto began = Clock::now();
    const std::vector<RunResult> part = evaluator.Evaluate(tables.subspan(start, count));
    const double seconds = SecondsSince(began);
    results.insert(results.end(), part.begin(), part.end());
    start += count;
    if (between)
      between("evaluations", static_cast<long long>(start), static_cast<long long>(tables.size()));
    const double per_creature = std::max(seconds, 1e-6) / static_cast<double>(count);
    slice = std::max(unit, static_cast<size_t>(slice_seconds / per_creature) / unit * unit);
  }
  return results;
}

std::unique_ptr<Evaluator> MakeEvaluator(const CreatureModel& model, const MotorProgram& program,
                                         const EvaluatorConfig& config) {
  if (MpiWorldSize() > 1) return MakeMpiEvaluator(model, program, config);
  return MakeLocalEvaluator(model, program, config);
}

}  // namespace hexgait
