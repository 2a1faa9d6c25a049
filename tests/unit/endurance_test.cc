// hexgait endurance's pieces: the run that stops at the fall, the push, the slope, and the
// study itself (same bits for any thread count, its long run the plain simulation's).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "eval/evaluator.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "same_result.h"
#include "sim/batch_evaluate.h"
#include "sim/evaluate.h"
#include "sim/forces.h"
#include "study/endurance.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

using test::SameBits;

void ExpectSameRun(const RunResult& a, const RunResult& b) {
  test::ExpectSameResult(a, b, "run");
}

struct Fixture {
  CreatureModel model = test::DefaultCreature();
  MotorProgram program = LoadMotorProgramOrDefault("", model);
  RestLengthTable unoptimized = GeometricRestLengths(model, program);
  RestLengthTable Random(uint64_t stream) const {
    Genome g(MakeGenomeLayout(model, program, false));
    Rng rng = Rng::ForStream(777, stream);
    for (int i = 0; i < g.num_genes(); ++i) g.set_gene(i, static_cast<int>(rng.NextBelow(7)) - 3);
    return PerturbedRestLengths(model, program, g);
  }
};

TEST(StopAtFall, EndsAtTheFallWithTheSameFall) {
  const Fixture f;
  RunOptions options;
  options.duration = 400;  // the unoptimized program falls in its third cycle, near t = 156
  const RunResult whole = EvaluateRestLengths(f.model, f.program, f.unoptimized, options);
  ASSERT_TRUE(whole.fell);
  options.stop_at_fall = true;
  const RunResult stopped = EvaluateRestLengths(f.model, f.program, f.unoptimized, options);
  EXPECT_TRUE(stopped.fell);
  EXPECT_TRUE(stopped.stopped_early);
  EXPECT_TRUE(SameBits(whole.fall_time, stopped.fall_time));
  EXPECT_EQ(stopped.steps, std::llround(whole.fall_time / options.dt));
  // The batched kernels stop the lane at the same check.
  const std::vector<RunResult> batched =
      EvaluateBatched(f.model, f.program, std::vector<RestLengthTable>{f.unoptimized}, options);
  ExpectSameRun(stopped, batched[0]);
}

TEST(Push, AddsItsImpulseToTheBodyAlongY) {
  const Fixture f;
  SimState state = MakeRestState(f.model);
  const auto momentum_y = [&] {
    double p = 0;
    for (int i = 0; i < state.num_particles(); ++i) p += f.model.mass[i] * state.vy[i];
    return p;
  };
  const double before = momentum_y();
  PushBody(f.model, 2.0, state);
  EXPECT_NEAR(momentum_y() - before, 2.0, 1e-12);
  for (const Leg& leg : f.model.legs) EXPECT_EQ(state.vy[leg.foot], 0.0) << "feet are not pushed";
}

TEST(Push, ChangesTheRunOnlyFromItsTimeAndRunsOnTheScalarPath) {
  const Fixture f;
  RunOptions options;
  options.duration = 120;
  const RunResult plain = EvaluateRestLengths(f.model, f.program, f.unoptimized, options);
  RunOptions late = options;
  late.push_impulse = 3;
  late.push_time = 500;  // after the end: no push
  ExpectSameRun(plain, EvaluateRestLengths(f.model, f.program, f.unoptimized, late));
  RunOptions pushed = options;
  pushed.push_impulse = 3;
  pushed.push_time = 60;
  const RunResult shoved = EvaluateRestLengths(f.model, f.program, f.unoptimized, pushed);
  EXPECT_FALSE(SameBits(plain.distance, shoved.distance));
  EXPECT_THROW(
      EvaluateBatched(f.model, f.program, std::vector<RestLengthTable>{f.unoptimized}, pushed),
      InputError);
  // The evaluator takes the scalar path for it, on any number of threads.
  EvaluatorConfig config;
  config.run = pushed;
  for (int threads : {1, 2}) {
    config.threads = threads;
    const std::vector<RestLengthTable> tables{f.unoptimized, f.Random(1), f.Random(2)};
    const std::vector<RunResult> results =
        MakeLocalEvaluator(f.model, f.program, config)->Evaluate(tables);
    for (size_t i = 0; i < tables.size(); ++i) {
      ExpectSameRun(EvaluateRestLengths(f.model, f.program, tables[i], pushed), results[i]);
    }
  }
}

TEST(Slope, TiltsTheWeightOfAFreeCreatureAndOnlyTheScalarPathTakesIt) {
  Fixture f;
  f.model.physics.gravity_x = -0.05;
  SimState state = MakeRestState(f.model);
  for (double& z : state.z) z += 10;  // in the air: springs and gravity only
  ComputeForces(f.model, state.rest_length.data(), state.particle_view(), state.force_view());
  double total_mass = 0, fx = 0, fy = 0, fz = 0;
  for (int i = 0; i < state.num_particles(); ++i) {
    total_mass += f.model.mass[i];
    fx += state.fx[i];
    fy += state.fy[i];
    fz += state.fz[i];
  }
  EXPECT_NEAR(fx, total_mass * -0.05, 1e-9);  // the springs' forces cancel in pairs
  EXPECT_NEAR(fy, 0.0, 1e-9);
  EXPECT_NEAR(fz, -total_mass * f.model.physics.gravity, 1e-9);
  RunOptions options;
  options.duration = 30;
  EXPECT_THROW(
      EvaluateBatched(f.model, f.program, std::vector<RestLengthTable>{f.unoptimized}, options),
      InputError);
  EvaluatorConfig config;
  config.run = options;
  config.threads = 2;
  const std::vector<RunResult> results =
      MakeLocalEvaluator(f.model, f.program, config)
          ->Evaluate(std::vector<RestLengthTable>{f.unoptimized});
  ExpectSameRun(EvaluateRestLengths(f.model, f.program, f.unoptimized, options), results[0]);
}

TEST(SurvivalCurve, StepsDownAtEachFallAndEndsAtTheHorizon) {
  const auto curve = SurvivalCurve({30, INFINITY, 10, 30, 500}, 100);
  const std::vector<std::pair<double, double>> expected{{0, 1.0}, {10, 0.8}, {30, 0.4}, {100, 0.4}};
  EXPECT_EQ(curve, expected);
}

EnduranceSettings TinySettings(int threads) {
  EnduranceSettings s;
  s.test.duration = 40;
  s.long_factor = 3;
  s.perturbed_factor = 2;
  s.trials = 2;
  s.threads = threads;
  return s;
}

TEST(Endurance, SameBitsForAnyThreadCountAndTheLongRunIsTheSimulation) {
  const Fixture f;
  const std::vector<EnduranceGait> gaits{
      {"a", "unoptimized", f.unoptimized}, {"a", "r1", f.Random(1)}, {"b", "r2", f.Random(2)}};
  const EnduranceResult one = RunEndurance(f.model, f.program, gaits, TinySettings(1));
  const EnduranceResult two = RunEndurance(f.model, f.program, gaits, TinySettings(2));
  // none, push x2, slope up, slope down, jitter x2, symplectic Euler, half step
  ASSERT_EQ(one.conditions.size(), 7u);
  ASSERT_EQ(one.runs.size(), 3u * 9u);
  ASSERT_EQ(one.runs.size(), two.runs.size());
  for (size_t i = 0; i < one.runs.size(); ++i) {
    SCOPED_TRACE(one.conditions[one.runs[i].condition].name);
    ExpectSameRun(one.runs[i].result, two.runs[i].result);
    EXPECT_TRUE(SameBits(one.runs[i].push_time, two.runs[i].push_time));
  }
  RunOptions long_run;
  long_run.duration = 120;
  long_run.stop_at_fall = true;
  for (int g = 0; g < 3; ++g) {
    ExpectSameRun(EvaluateRestLengths(f.model, f.program, gaits[g].table, long_run),
                  one.runs[g].result);
  }
  // The push lands after the test, within one gait cycle, on a step.
  for (const EnduranceRun& r : one.runs) {
    if (one.conditions[r.condition].perturbation != Perturbation::kPush) continue;
    EXPECT_GE(r.push_time, 40.0);
    EXPECT_LE(r.push_time, 40.0 + f.program.cycle_period);
  }
}

TEST(Endurance, RefusesSettingsOutOfRange) {
  EnduranceSettings s = TinySettings(1);
  s.perturbed_factor = 1;
  EXPECT_THROW(CheckEnduranceSettings(s), InputError);
  s = TinySettings(1);
  s.jitter = 0.7;
  EXPECT_THROW(CheckEnduranceSettings(s), InputError);
  s = TinySettings(1);
  s.slope_degrees = 60;
  EXPECT_THROW(CheckEnduranceSettings(s), InputError);
}

TEST(Endurance, RandomGenomesStandTheTestAndDoNotDependOnThreads) {
  const Fixture f;
  RunOptions test;
  test.duration = 200;
  const auto layout = MakeGenomeLayout(f.model, f.program, false);
  int tried1 = 0, tried2 = 0;
  const std::vector<Genome> a =
      StandingRandomGenomes(f.model, f.program, layout, 2, 640, test, 5, 1, &tried1);
  const std::vector<Genome> b =
      StandingRandomGenomes(f.model, f.program, layout, 2, 640, test, 5, 2, &tried2);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(tried1, tried2);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i] == b[i]);
    EXPECT_FALSE(EvaluateGenome(f.model, f.program, a[i], test).fell);
  }
}

}  // namespace
}  // namespace hexgait
