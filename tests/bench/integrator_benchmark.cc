// One step of every integrator on the standing creature (feet in contact), without the
// controller: the per-step cost behind `hexgait bench accuracy`'s time column.
//   build/hexgait_integrator_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "motor/assets.h"
#include "sim/step_loop.h"
#include "sim/steppers.h"

namespace hexgait {
namespace {

void BM_IntegratorStep(benchmark::State& bench_state, IntegratorKind kind) {
  static const CreatureModel model = LoadCreatureOrDefault("");
  SimState s = MakeRestState(model);
  WithStepper(kind, model, [&](auto& stepper) {
    stepper.Begin(model, s);
    for (int i = 0; i < 1000; ++i) stepper.Step(model, s, kPaperTimeStep);  // warm up, settle
    for (auto _ : bench_state) {
      stepper.Step(model, s, kPaperTimeStep);
      benchmark::DoNotOptimize(s.x.data());
    }
  });
  bench_state.counters["force_evals"] = ForceEvaluationsPerStep(kind);
  bench_state.counters["ns/step"] =
      benchmark::Counter(static_cast<double>(bench_state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_IntegratorStep, euler, IntegratorKind::kEuler);
BENCHMARK_CAPTURE(BM_IntegratorStep, symplectic_euler, IntegratorKind::kSymplecticEuler);
BENCHMARK_CAPTURE(BM_IntegratorStep, verlet, IntegratorKind::kVerlet);
BENCHMARK_CAPTURE(BM_IntegratorStep, rk4, IntegratorKind::kRk4);
BENCHMARK_CAPTURE(BM_IntegratorStep, implicit_euler, IntegratorKind::kImplicitEuler);

}  // namespace
}  // namespace hexgait

BENCHMARK_MAIN();
