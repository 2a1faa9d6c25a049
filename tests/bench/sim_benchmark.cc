// Micro-benchmarks (Google Benchmark), built as build/hexgait_bench and never run as tests.
//   build/hexgait_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// reports medians; see docs/speed.md.
#include <benchmark/benchmark.h>

#include "bench/naive_stepper.h"
#include "bench/speed.h"
#include "ga/evolution.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/assets.h"
#include "motor/batch_controller.h"
#include "motor/controller.h"
#include "motor/lane_clocked_controller.h"
#include "motor/leg_targets.h"
#include "search/ga_optimizer.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_kernel.h"
#include "sim/batch_state.h"
#include "sim/creature_simulation.h"
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

// The same step written the plain way (src/bench/naive_stepper.h): arrays of Eigen vectors.
void BM_NaiveStep(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  NaiveState s = MakeNaiveState(scene.model);
  const std::vector<double> rest = scene.model.rest_length;
  for (int i = 0; i < 1000; ++i) NaiveEulerStep(scene.model, rest.data(), s, kPaperTimeStep);
  for (auto _ : state) {
    NaiveEulerStep(scene.model, rest.data(), s, kPaperTimeStep);
    benchmark::DoNotOptimize(s.position.data());
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NaiveStep);

// One batched step of `lanes` creatures (the argument) of type T under the controller, walking;
// the ns/creature-step counter divides by the lanes.
template <class T>
void BM_BatchedStep(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  const int lanes = static_cast<int>(state.range(0));
  const RestLengthTable table = GeometricRestLengths(scene.model, scene.program);
  BatchMotorController controller(scene.model, scene.program,
                                  std::vector<RestLengthTable>(lanes, table), kPaperTimeStep);
  BatchStateT<T> b = MakeBatchStateT<T>(scene.model, MakeRestState(scene.model), lanes);
  const BatchKernelArgsT<T> args = MakeBatchKernelArgs(scene.model, b, kPaperTimeStep);
  const BatchStepFnT<T> step = SelectBatchStepT<T>(lanes);
  long long k = 0;
  for (auto _ : state) {
    controller.Update(k++, b.rest_length.data());
    step(args);
    benchmark::DoNotOptimize(b.state.data());
  }
  state.counters["ns/creature-step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * lanes,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(BatchIsaName(BatchIsa::kAuto));
}
BENCHMARK_TEMPLATE(BM_BatchedStep, double)->Arg(1)->Arg(4)->Arg(8)->Arg(16);
BENCHMARK_TEMPLATE(BM_BatchedStep, float)->Arg(1)->Arg(4)->Arg(8)->Arg(16);

// The refilled lanes' motor controller alone (LaneClockedController::Update), for `lanes`
// creatures (the argument) of type T whose clocks are 1,000 steps apart, as refilling leaves
// them: one batch step's instructions and every leg spring's rest length. A tenth of a
// repertoire's time (docs/speed.md, "The repertoire's controller in one call").
template <class T>
void BM_LaneClockedController(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  const int lanes = static_cast<int>(state.range(0));
  const RestLengthTable table = GeometricRestLengths(scene.model, scene.program);
  LaneClockedController controller(scene.model, scene.program, lanes, kPaperTimeStep);
  std::vector<T> rest(static_cast<size_t>(scene.model.num_springs()) * lanes, T(1));
  constexpr long long kApart = 1000;
  long long k = 0;
  for (; k < lanes * kApart; ++k) {
    if (k % kApart == 0) controller.StartLane(static_cast<int>(k / kApart), table, k, rest.data());
    controller.Update(k, rest.data());
  }
  for (auto _ : state) {
    controller.Update(k++, rest.data());
    benchmark::DoNotOptimize(rest.data());
  }
  state.counters["ns/creature-step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * lanes,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(BatchIsaName(BatchIsa::kAuto));
}
BENCHMARK_TEMPLATE(BM_LaneClockedController, double)->Arg(8)->Arg(16);
BENCHMARK_TEMPLATE(BM_LaneClockedController, float)->Arg(16);

// One step of `count` creatures (the argument) on the float creature kernel, controller
// included; skipped without AVX-512.
void BM_CreatureStep(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  if (!CreatureSimulation::Available(scene.model)) {
    state.SkipWithError("no AVX-512 on this CPU");
    return;
  }
  const int count = static_cast<int>(state.range(0));
  const Genome genome(MakeGenomeLayout(scene.model, scene.program, false));
  const std::vector<const Genome*> genomes(count, &genome);
  CreatureSimulation sim(scene.model, scene.program,
                         PerturbedRestLengths(scene.model, scene.program, genomes), kPaperTimeStep);
  for (auto _ : state) sim.Advance(1);
  state.counters["ns/creature-step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * count,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_CreatureStep)->Arg(1)->Arg(2)->Arg(4);

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

// 16 evaluations in lock-step on one core (1000 time units each); per-evaluation time in the
// counter.
void BM_BatchedEvaluation16(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  const Genome genome(MakeGenomeLayout(scene.model, scene.program, false));
  const std::vector<const Genome*> genomes(16, &genome);
  RunOptions options;
  for (auto _ : state) {
    const std::vector<RunResult> r =
        EvaluateGenomesBatched(scene.model, scene.program, genomes, options);
    benchmark::DoNotOptimize(r[0].distance);
  }
  state.counters["ms/evaluation"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 16 * 1e-3,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BatchedEvaluation16)->Unit(benchmark::kMillisecond);

// 16 evaluations in float lanes as `hexgait bench speed` times them (its random genomes: most
// fall, and every lane is on its own path), fall checks included: the workload its
// ns_per_creature_step_batched_float measures, for profiling (docs/speed.md).
void BM_BatchedFloatEvaluation16(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  const std::vector<Genome> genomes = SpeedGenomes(scene.model, scene.program, 16);
  std::vector<const Genome*> batch;
  for (const Genome& g : genomes) batch.push_back(&g);
  RunOptions options;
  for (auto _ : state) {
    const std::vector<RunResult> r = EvaluateGenomesBatched(
        scene.model, scene.program, batch, options, 16, BatchIsa::kAuto, Precision::kFloat);
    benchmark::DoNotOptimize(r[0].distance);
  }
  state.counters["ns/creature-step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 16 * 400000.0,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BatchedFloatEvaluation16)->Unit(benchmark::kMillisecond);

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

// The same, one creature at a time (the scalar path, as before batching), on all cores.
void BM_EvolvePaperDefaultsScalar(benchmark::State& state) {
  const Scene& scene = DefaultScene();
  EvolutionParams params;
  params.batch_lanes = 1;
  for (auto _ : state) {
    const EvolutionResult r = Evolve(scene.model, scene.program, params, {});
    benchmark::DoNotOptimize(r.best->fitness);
  }
}
BENCHMARK(BM_EvolvePaperDefaultsScalar)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace hexgait

BENCHMARK_MAIN();
