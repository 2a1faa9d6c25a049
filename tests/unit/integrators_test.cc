// The integrators' defining properties, on the contact-free free-flight problem
// (bench/free_flight.h) where the exact solution is smooth: convergence order, bounded energy
// for the symplectic methods, and the implicit method's stability where explicit Euler fails.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/free_flight.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/reference.h"
#include "sim/step_loop.h"
#include "sim/steppers.h"
#include "test_util.h"
#include "tolerances.h"

namespace hexgait {
namespace {

// Positions after `duration` with `kind` at step dt, from the free-flight start.
SimState Advance(const FreeFlight& f, IntegratorKind kind, double dt, double duration) {
  SimState s = f.initial;
  const long long steps = std::llround(duration / dt);
  WithStepper(kind, f.model, [&](auto& stepper) {
    stepper.Begin(f.model, s);
    for (long long k = 0; k < steps; ++k) stepper.Step(f.model, s, dt);
  });
  return s;
}

double MaxPositionError(const SimState& a, const SimState& b) {
  double worst = 0;
  for (int i = 0; i < a.num_particles(); ++i)
    worst = std::fmax(worst, (a.position(i) - b.position(i)).norm());
  return worst;
}

const FreeFlight& DampedFlight() {
  static const FreeFlight flight = MakeFreeFlight(test::DefaultCreature(), true);
  return flight;
}

// The adaptive reference at t = 2 for the damped free flight (fixed rest lengths).
const SimState& ReferenceAt2() {
  static const SimState ref = [] {
    ReferenceSolver solver(DampedFlight().model, nullptr, DampedFlight().initial, 1e-12);
    solver.AdvanceTo(2.0);
    return solver.state();
  }();
  return ref;
}

// Observed order log2(e(dt) / e(dt/2)) against the reference, with damping on (so Verlet's
// velocity-dependent forces are exercised).
double ObservedOrder(IntegratorKind kind, double dt) {
  const double e1 = MaxPositionError(Advance(DampedFlight(), kind, dt, 2.0), ReferenceAt2());
  const double e2 = MaxPositionError(Advance(DampedFlight(), kind, dt / 2, 2.0), ReferenceAt2());
  return std::log2(e1 / e2);
}

TEST(Integrators, ConvergenceOrderWithoutContact) {
  EXPECT_NEAR(ObservedOrder(IntegratorKind::kEuler, 0.0005), 1.0, 0.15);
  EXPECT_NEAR(ObservedOrder(IntegratorKind::kSymplecticEuler, 0.001), 1.0, 0.15);
  EXPECT_NEAR(ObservedOrder(IntegratorKind::kVerlet, 0.002), 2.0, 0.15);
  EXPECT_NEAR(ObservedOrder(IntegratorKind::kRk4, 0.005), 4.0, 0.3);
  EXPECT_NEAR(ObservedOrder(IntegratorKind::kImplicitEuler, 0.0005), 1.0, 0.15);
}

TEST(Integrators, AllConvergeToTheReference) {
  // At a fine step every method agrees with the adaptive reference: no method is consistent
  // with a different equation. (At dt 0.0005 the first-order methods are 5.4e-3 (Euler) and
  // 5.2e-3 (implicit Euler) from it on the hexapod's flight, 10x finer they are within 1e-3.)
  for (IntegratorKind kind : AllIntegrators()) {
    const double dt = kind == IntegratorKind::kRk4 ? 0.005 : 0.00005;
    EXPECT_LT(MaxPositionError(Advance(DampedFlight(), kind, dt, 2.0), ReferenceAt2()), 1e-3)
        << IntegratorName(kind);
  }
}

// Largest |E(t) - E(0)| over 100 time units of undamped free flight, relative to the initial
// vibration energy, sampled every time unit.
double MaxEnergyDrift(IntegratorKind kind, double dt) {
  const FreeFlight f = MakeFreeFlight(test::DefaultCreature(), false);
  SimState s = f.initial;
  const double e0 = TotalEnergy(f.model, s);
  double worst = 0;
  const long long every = std::llround(1.0 / dt);
  WithStepper(kind, f.model, [&](auto& stepper) {
    stepper.Begin(f.model, s);
    for (long long k = 1; k <= 100 * every; ++k) {
      stepper.Step(f.model, s, dt);
      if (k % every == 0) {
        const double drift = std::fabs(TotalEnergy(f.model, s) - e0) / f.vibration_energy;
        worst = std::fmax(worst, std::isfinite(drift) ? drift : INFINITY);
      }
    }
  });
  return worst;
}

TEST(Integrators, SymplecticMethodsKeepEnergyBounded) {
  // Bounded, oscillating error (no secular growth) for the symplectic methods ...
  EXPECT_LT(MaxEnergyDrift(IntegratorKind::kSymplecticEuler, 0.0025), 0.05);
  EXPECT_LT(MaxEnergyDrift(IntegratorKind::kVerlet, 0.0025), 0.01);
  // ... while explicit Euler pumps energy in without bound at the same step.
  EXPECT_GT(MaxEnergyDrift(IntegratorKind::kEuler, 0.0025), 1.0);
}

// A creature with every spring 100 times stiffer, run with the paper's program.
RunResult RunStiff(IntegratorKind kind, double dt, double duration) {
  CreatureModel model = test::DefaultCreature();
  for (double& k : model.stiffness) k *= 100;
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  MotorController controller(model, program, PerturbedRestLengths(model, program, genome), dt);
  SimState state = MakeRestState(model);
  RunOptions options;
  options.dt = dt;
  options.duration = duration;
  options.integrator = kind;
  NullObserver none;
  return Simulate(model, controller, state, options, none);
}

TEST(Integrators, ImplicitEulerSurvivesWhereExplicitEulerDiverges) {
  const RunResult explicit_run = RunStiff(IntegratorKind::kEuler, 0.0025, 10);
  const RunResult implicit_run = RunStiff(IntegratorKind::kImplicitEuler, 0.0025, 10);
  EXPECT_TRUE(explicit_run.diverged);
  EXPECT_FALSE(implicit_run.diverged);
  EXPECT_TRUE(std::isfinite(implicit_run.distance));
}

TEST(Integrators, DivergenceIsDetectedWithTimeAndStep) {
  const double dt = 0.0025;
  const RunResult r = RunStiff(IntegratorKind::kEuler, dt, 10);
  ASSERT_TRUE(r.diverged);
  EXPECT_GT(r.diverge_time, 0.0);
  EXPECT_LT(r.diverge_time, 10.0);
  EXPECT_EQ(r.diverge_step, std::llround(r.diverge_time / dt));
  EXPECT_FALSE(r.diverge_reason.empty());
  EXPECT_EQ(r.distance, 0.0);  // never a garbage distance
}

// simulate and figures run in chunks for their progress bar: every integrator must give the
// same bits as one Simulate call, including a chunk size that splits the check interval and a
// run that ends in a fall check mid-chunk.
// The checks stay 0.1 time units apart at every step: 40 steps at the paper's, 80 at half of it
// (endurance's other step), the nearest whole number otherwise, and never fewer than 1.
TEST(Integrators, CheckIntervalIsATenthOfATimeUnit) {
  EXPECT_EQ(CheckIntervalFor(kPaperTimeStep), 40);
  EXPECT_EQ(CheckIntervalFor(kPaperTimeStep * 0.5), 80);
  EXPECT_EQ(CheckIntervalFor(0.003), 33);
  EXPECT_EQ(CheckIntervalFor(0.0015), 67);
  EXPECT_EQ(CheckIntervalFor(1.0), 1);
  EXPECT_EQ(RunOptions().check_interval, CheckIntervalFor(RunOptions().dt));
}

TEST(Integrators, SimulateInChunksIsBitIdenticalToOnePiece) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  for (IntegratorKind kind :
       {IntegratorKind::kEuler, IntegratorKind::kSymplecticEuler, IntegratorKind::kVerlet,
        IntegratorKind::kRk4, IntegratorKind::kImplicitEuler}) {
    RunOptions options;
    options.integrator = kind;
    options.duration = 30;
    const auto run = [&](long long chunk, long long* calls) {
      MotorController controller(model, program, PerturbedRestLengths(model, program, genome),
                                 options.dt);
      SimState state = MakeRestState(model);
      NullObserver none;
      RunResult r = chunk == 0 ? Simulate(model, controller, state, options, none)
                               : SimulateInChunks(model, controller, state, options, none, chunk,
                                                  [&](long long, long long) { ++*calls; });
      return std::pair{r, state};
    };
    long long calls = 0;
    const auto [whole, whole_state] = run(0, &calls);
    const auto [chunked, chunked_state] = run(777, &calls);
    EXPECT_EQ(calls, whole.steps / 777) << IntegratorName(kind);
    EXPECT_EQ(whole.distance, chunked.distance) << IntegratorName(kind);
    EXPECT_EQ(whole.steps, chunked.steps);
    EXPECT_EQ(whole.fell, chunked.fell);
    EXPECT_EQ(whole.min_body_height, chunked.min_body_height);
    EXPECT_EQ(whole.mean_feet_on_ground, chunked.mean_feet_on_ground);
    for (int i = 0; i < model.num_particles(); ++i) {
      EXPECT_EQ(whole_state.position(i), chunked_state.position(i)) << IntegratorName(kind);
    }
  }
}

TEST(Reference, HalvingTheToleranceChangesLittle) {
  // The accuracy bench's reference tolerance (1e-10) and half of it, over 10 time units of the
  // damped free flight: the difference must be far below the smallest error the bench reports
  // (~1e-6).
  const FreeFlight& f = DampedFlight();
  ReferenceSolver a(f.model, nullptr, f.initial, 1e-10);
  ReferenceSolver b(f.model, nullptr, f.initial, 5e-11);
  a.AdvanceTo(10.0);
  b.AdvanceTo(10.0);
  EXPECT_LT(MaxPositionError(a.state(), b.state()), 1e-8);
  EXPECT_GT(a.steps(), 100);
}

}  // namespace
}  // namespace hexgait
