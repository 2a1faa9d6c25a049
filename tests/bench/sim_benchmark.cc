// Micro-benchmarks (Google Benchmark), built as build/hexgait_bench and never run as tests.
//   build/hexgait_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// reports medians; see README.md ("Speed").
#include <benchmark/benchmark.h>

#include "app/assets.h"
#include "ga/evolution.h"
#include "ga/genome.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/evaluate.h"
#include "sim/integrator.h"

namespace hexgait {
namespace {

struct Scene {
  CreatureModel model = LoadCreatureOrDefault("");
  MotorProgram program = LoadMotorProgramOrDefault("", model);
};

const Scene& DefaultScene() {
  static const Scene scene;
  return scene;
}

// One explicit Euler step of the creature (forces + update), without the controller.
void BM_EulerStep(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  SimState s = MakeRestState(scene.model);
  for (int i = 0; i < 1000; ++i) EulerStepper::Step(scene.model, s, kPaperTimeStep);  // warm up
  for (auto _ : state) {
    EulerStepper::Step(scene.model, s, kPaperTimeStep);
    benchmark::DoNotOptimize(s.x.data());
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EulerStep);

// One fitness evaluation as the GA makes it: 1000 time units, 400,000 steps, one core.
void BM_FitnessEvaluation(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  const Genome genome(MakeGenomeLayout(scene.model, scene.program, false));
  RunOptions options;
  for (auto _ : state) {
    const RunResult r = EvaluateGenome(scene.model, scene.program, genome, options);
    benchmark::DoNotOptimize(r.distance);
  }
  state.counters["ns/step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 400000.0,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FitnessEvaluation)->Unit(benchmark::kMillisecond);

// The paper's whole experiment: `hexgait evolve` defaults (population 4, 10 generations),
// evaluations spread over all cores.
void BM_EvolvePaperDefaults(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  EvolutionParams params;
  params.threads = static_cast<int>(state.range(0));
  int evaluations = 0;
  for (auto _ : state) {
    const EvolutionResult r = Evolve(scene.model, scene.program, params, {});
    evaluations = r.total_evaluations;
    benchmark::DoNotOptimize(r.best->fitness);
  }
  state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_EvolvePaperDefaults)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace hexgait

BENCHMARK_MAIN();
