// The batched simulator against the scalar path: bit for bit, on every instruction set this
// CPU has, for walking, falling and diverging creatures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "bench/naive_stepper.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "ga/rng.h"
#include "motor/batch_controller.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "same_result.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_kernel.h"
#include "sim/batch_state.h"
#include "sim/evaluate.h"
#include "test_util.h"
#include "tolerances.h"
#include "util/error.h"

namespace hexgait {
namespace {

using test::ExpectSameResult;
using test::SameBits;

using test::RandomGenome;
using test::SupportedIsas;

// Every lane's particle state after many steps under the controller equals the scalar run's.
// One rule says which runs the batched paths accept, and the batched evaluator refuses the
// others with its reason (the local evaluator sends those to the scalar path by the same rule).
TEST(Batch, OneRuleSaysWhichRunsTheBatchedPathsAccept) {
  CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 1;
  EXPECT_TRUE(BatchedPathAccepts(model, options));
  const std::vector<RestLengthTable> tables(2, GeometricRestLengths(model, program));
  const auto refused_with = [&](const RunOptions& o, const std::string& why) {
    EXPECT_FALSE(BatchedPathAccepts(model, o));
    EXPECT_EQ(BatchedPathRefusal(model, o), why);
    try {
      EvaluateBatched(model, program, tables, o);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), "the batched simulator " + why);
    }
  };
  RunOptions rk4 = options;
  rk4.integrator = IntegratorKind::kRk4;
  refused_with(rk4, "runs the explicit Euler integrator only");
  RunOptions push = options;
  push.push_impulse = 1;
  refused_with(push, "does not push");
  model.physics.gravity_x = 0.1;
  refused_with(options, "models flat ground only (gravity along -z)");
}

TEST(Batch, LanesEqualTheScalarStepBitForBit) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const int lanes = 4;
  const long long steps = 6000;  // 15 time units: several instructions and transitions
  std::vector<SimState> scalar;
  std::vector<RestLengthTable> tables;
  for (int l = 0; l < lanes; ++l) {
    const Genome genome = RandomGenome(model, program, static_cast<uint64_t>(l));
    tables.push_back(PerturbedRestLengths(model, program, genome));
    MotorController controller(model, program, tables.back(), kPaperTimeStep);
    SimState s = MakeRestState(model);
    for (long long k = 0; k < steps; ++k) {
      controller.Update(k, s.rest_length.data());
      EulerStepper::Step(model, s, kPaperTimeStep);
    }
    scalar.push_back(s);
  }
  for (BatchIsa isa : SupportedIsas()) {
    SCOPED_TRACE(BatchIsaName(isa));
    BatchMotorController controller(model, program, tables, kPaperTimeStep);
    BatchState b = MakeBatchState(model, MakeRestState(model), lanes);
    const BatchKernelArgs args = MakeBatchKernelArgs(model, b, kPaperTimeStep);
    const BatchStepFn step = SelectBatchStep(lanes, isa);
    for (long long k = 0; k < steps; ++k) {
      controller.Update(k, b.rest_length.data());
      step(args);
    }
    SimState lane = MakeRestState(model);
    for (int l = 0; l < lanes; ++l) {
      ExtractLane(b, l, lane);
      for (int i = 0; i < model.num_particles(); ++i) {
        ASSERT_TRUE(SameBits(lane.x[i], scalar[l].x[i])) << "lane " << l << " particle " << i;
        ASSERT_TRUE(SameBits(lane.z[i], scalar[l].z[i])) << "lane " << l << " particle " << i;
        ASSERT_TRUE(SameBits(lane.vy[i], scalar[l].vy[i])) << "lane " << l << " particle " << i;
      }
      for (int s = 0; s < model.num_springs(); ++s) {
        ASSERT_TRUE(SameBits(lane.rest_length[s], scalar[l].rest_length[s]));
      }
    }
  }
}

// Whole evaluations: a walker, fallers and diverging runs in one batch, each equal to its
// scalar EvaluateGenome, for every lane count and instruction set.
void CheckBatchAgainstScalar(double dt, bool want_divergence) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 60;
  options.dt = dt;
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Genome> genomes;
  genomes.emplace_back(layout);  // the unoptimised program
  Genome low(layout), high(layout);
  for (int i = 0; i < low.num_genes(); ++i) {
    low.set_gene(i, -8);
    high.set_gene(i, 7);
  }
  genomes.push_back(low);
  genomes.push_back(high);
  for (uint64_t k = 0; k < 3; ++k) genomes.push_back(RandomGenome(model, program, 100 + k));

  std::vector<RunResult> scalar;
  for (const Genome& g : genomes) scalar.push_back(EvaluateGenome(model, program, g, options));
  int fell = 0, diverged = 0;
  for (const RunResult& r : scalar) {
    fell += r.fell;
    diverged += r.diverged;
  }
  EXPECT_GT(fell, 0) << "the batch should include a creature that falls";
  if (want_divergence) {
    // Lanes must stop at different steps, or the test proves little about freezing them.
    std::vector<long long> stops;
    for (const RunResult& r : scalar) stops.push_back(r.diverged ? r.diverge_step : -1);
    std::sort(stops.begin(), stops.end());
    EXPECT_GT(diverged, 0) << "some runs should diverge at this step";
    EXPECT_GT(std::unique(stops.begin(), stops.end()) - stops.begin(), 2);
  } else {
    EXPECT_EQ(diverged, 0);
  }

  std::vector<const Genome*> pointers;
  for (const Genome& g : genomes) pointers.push_back(&g);
  for (BatchIsa isa : SupportedIsas()) {
    for (int lanes : {8, 16}) {
      SCOPED_TRACE(BatchIsaName(isa) + " x" + std::to_string(lanes));
      const std::vector<RunResult> batched =
          EvaluateGenomesBatched(model, program, pointers, options, lanes, isa);
      ASSERT_EQ(batched.size(), genomes.size());
      for (size_t i = 0; i < genomes.size(); ++i) ExpectSameResult(scalar[i], batched[i], "lane");
    }
  }
}

TEST(Batch, EvaluationsEqualTheScalarPathIncludingFalls) {
  CheckBatchAgainstScalar(kPaperTimeStep, false);
}

// Past explicit Euler's limit the creatures diverge, each at its own step: each lane's result
// freezes where its scalar run stops while the others go on.
TEST(Batch, EvaluationsEqualTheScalarPathIncludingDivergence) {
  CheckBatchAgainstScalar(0.011, true);
}

// Float lanes: every lane runs the same float operations whatever the lane count and the
// instruction set, so results are the same bits for any batch size and thread count.
TEST(FloatLanes, SameBitsForEveryLaneCountAndInstructionSet) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 60;
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Genome> genomes;
  genomes.emplace_back(layout);
  for (uint64_t k = 0; k < 5; ++k) genomes.push_back(RandomGenome(model, program, 200 + k));
  std::vector<const Genome*> pointers;
  for (const Genome& g : genomes) pointers.push_back(&g);

  std::vector<RunResult> alone;  // each genome in a batch of its own, on the generic kernel
  for (const Genome& g : genomes) {
    alone.push_back(EvaluateGenomesBatched(model, program, {&g}, options, 1, BatchIsa::kGeneric,
                                           Precision::kFloat)
                        .front());
  }
  int fell = 0;
  for (const RunResult& r : alone) fell += r.fell;
  EXPECT_GT(fell, 0) << "the batch should include a creature that falls";
  for (BatchIsa isa : SupportedIsas()) {
    for (int lanes : {8, 16}) {
      SCOPED_TRACE(BatchIsaName(isa) + " x" + std::to_string(lanes));
      const std::vector<RunResult> batched =
          EvaluateGenomesBatched(model, program, pointers, options, lanes, isa, Precision::kFloat);
      for (size_t i = 0; i < genomes.size(); ++i) ExpectSameResult(alone[i], batched[i], "lane");
    }
  }
}

// The float kernel is the scalar step in float: one lane against a plain float loop written
// from sim/forces.cc (same expressions, same order) after 4000 steps of walking.
TEST(FloatLanes, EqualAPlainFloatStepBitForBit) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome = RandomGenome(model, program, 7);
  const int n = model.num_particles();
  const long long steps = 4000;
  BatchSimulation<float> sim(model, program, PerturbedRestLengths(model, program, {&genome}),
                             kPaperTimeStep, 1);
  sim.Advance(steps);

  BatchMotorController controller(model, program, {PerturbedRestLengths(model, program, genome)},
                                  kPaperTimeStep);
  std::vector<float> x(n), y(n), z(n), vx(n, 0), vy(n, 0), vz(n, 0), fx(n), fy(n), fz(n);
  for (int i = 0; i < n; ++i) {
    x[i] = static_cast<float>(model.rest_position[i].x());
    y[i] = static_cast<float>(model.rest_position[i].y());
    z[i] = static_cast<float>(model.rest_position[i].z());
  }
  std::vector<float> rest(model.rest_length.begin(), model.rest_length.end());
  const PhysicsConstants& ph = model.physics;
  const float g = static_cast<float>(ph.gravity), kg = static_cast<float>(ph.ground_stiffness);
  const float dg = static_cast<float>(ph.ground_damping), mu = static_cast<float>(ph.friction);
  const float eps2 = static_cast<float>(ph.slip_velocity * ph.slip_velocity);
  const float dt = static_cast<float>(kPaperTimeStep);
  for (long long k = 0; k < steps; ++k) {
    controller.Update(k, rest.data());
    for (int i = 0; i < n; ++i) {
      fx[i] = 0;
      fy[i] = 0;
      fz[i] = -static_cast<float>(model.mass[i]) * g;
    }
    for (int s = 0; s < model.num_springs(); ++s) {
      const int a = model.spring_a[s], b = model.spring_b[s];
      const float dx = x[b] - x[a], dy = y[b] - y[a], dz = z[b] - z[a];
      const float length = std::sqrt(dx * dx + dy * dy + dz * dz);
      const float inv = 1.0f / length;
      const float ux = dx * inv, uy = dy * inv, uz = dz * inv;
      const float rate = (vx[b] - vx[a]) * ux + (vy[b] - vy[a]) * uy + (vz[b] - vz[a]) * uz;
      const float m = static_cast<float>(model.stiffness[s]) * (length - rest[s]) +
                      static_cast<float>(model.damping[s]) * rate;
      fx[a] += m * ux, fy[a] += m * uy, fz[a] += m * uz;
      fx[b] -= m * ux, fy[b] -= m * uy, fz[b] -= m * uz;
    }
    for (int i = 0; i < n; ++i) {
      if (z[i] >= 0) continue;
      const float normal = -kg * z[i] - dg * vz[i];
      if (normal <= 0) continue;
      const float scale = mu * normal / std::sqrt(vx[i] * vx[i] + vy[i] * vy[i] + eps2);
      fz[i] += normal;
      fx[i] -= scale * vx[i];
      fy[i] -= scale * vy[i];
    }
    for (int i = 0; i < n; ++i) {
      const float h = dt * static_cast<float>(model.inv_mass[i]);
      x[i] += dt * vx[i], y[i] += dt * vy[i], z[i] += dt * vz[i];
      vx[i] += h * fx[i], vy[i] += h * fy[i], vz[i] += h * fz[i];
    }
  }
  SimState lane = MakeRestState(model);
  sim.Extract(0, lane);
  double moved = 0;
  for (int i = 0; i < n; ++i) {
    ASSERT_TRUE(SameBits(lane.x[i], x[i])) << i << ": " << lane.x[i] << " vs " << x[i];
    ASSERT_TRUE(SameBits(lane.z[i], z[i])) << i;
    ASSERT_TRUE(SameBits(lane.vy[i], vy[i])) << i;
    moved = std::max(moved, std::fabs(lane.x[i] - model.rest_position[i].x()));
  }
  EXPECT_GT(moved, 0.05) << "the creature should have moved, or the comparison proves little";
}

// What float costs in accuracy, on the seed-1 evolved program over the paper's 1000 time
// units: measured 2.7e-5 relative on the hexapod (best of `hexgait evolve --seed 1`: 7.713800
// in double, 7.714010 with --precision float; 3.4e-5 on the wedge), so a bound of 3e-4 can fail.
TEST(FloatLanes, FitnessOfTheEvolvedProgramIsCloseToDouble) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome =
      LoadGenomeFile(std::string(HEXGAIT_SOURCE_DIR "/tests/data/evolved_seed1.genome"),
                     MakeGenomeLayout(model, program, false));
  const RunOptions options;  // the paper's 1000 time units at dt 0.0025
  const RunResult d = EvaluateGenome(model, program, genome, options);
  const RunResult f = EvaluateGenomesBatched(model, program, {&genome}, options, 1, BatchIsa::kAuto,
                                             Precision::kFloat)
                          .front();
  ASSERT_FALSE(d.fell);
  EXPECT_FALSE(f.fell);
  EXPECT_NEAR(f.distance, d.distance, 3e-4 * d.distance);
  EXPECT_NE(f.distance, d.distance) << "float should not give double's bits";
}

}  // namespace
}  // namespace hexgait

namespace hexgait {
namespace {

// The benchmark's plain Eigen loop computes the same physics as the scalar kernel: only the
// rounding differs (d / L instead of d * (1 / L), ...), so over 10 time units of walking the
// two agree to about 1e-9.
TEST(NaiveStepper, AgreesWithTheScalarPath) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const RestLengthTable table = GeometricRestLengths(model, program);
  MotorController scalar_controller(model, program, table, kPaperTimeStep);
  MotorController naive_controller(model, program, table, kPaperTimeStep);
  SimState s = MakeRestState(model);
  NaiveState naive = MakeNaiveState(model);
  std::vector<double> naive_rest = model.rest_length;
  for (long long k = 0; k < 4000; ++k) {
    scalar_controller.Update(k, s.rest_length.data());
    EulerStepper::Step(model, s, kPaperTimeStep);
    naive_controller.Update(k, naive_rest.data());
    NaiveEulerStep(model, naive_rest.data(), naive, kPaperTimeStep);
  }
  double moved = 0;
  for (int i = 0; i < model.num_particles(); ++i) {
    EXPECT_NEAR((naive.position[i] - s.position(i)).norm(), 0.0, 1e-8 * test::TolScale()) << i;
    EXPECT_NEAR((naive.velocity[i] - s.velocity(i)).norm(), 0.0, 1e-8 * test::TolScale()) << i;
    moved = std::max(moved, (s.position(i) - model.rest_position[i]).norm());
  }
  EXPECT_GT(moved, 0.05) << "the legs should have moved, or the comparison proves little";
}

// The benchmark's peak is the peak loop's flops over its time: with m = 1 and a = 0 every chain
// keeps its start (1 + j and 2 + j in each lane), so the sum it returns counts the chains and
// lanes PeakLoopFlops counts. Its chains and m and a fit the vector registers (32 with AVX-512,
// 16 without), or the loop would time spills to memory instead of arithmetic.
TEST(PeakLoop, PerformsTheFlopsItsCountSaysInRegisters) {
  for (BatchIsa isa : SupportedIsas()) {
    for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
      SCOPED_TRACE(BatchIsaName(isa) + " " + PrecisionName(precision));
      const int lanes = NativeBatchLanes(isa, precision);
      ASSERT_EQ(PeakLoopFlops(isa, precision) % (2 * lanes), 0);
      const int chains = PeakLoopFlops(isa, precision) / (2 * lanes);
      double expected = 0;
      for (int j = 0; j < chains; ++j) expected += lanes * ((1.0 + j) + (2.0 + j));
      EXPECT_EQ(RunPeakLoop(isa, 10, 1.0, 0.0, precision), expected);
      EXPECT_GE(chains, 6) << "too few chains to cover two pipes' latency";
      EXPECT_LE(2 * chains + 2, SelectBatchKernels(isa).vector_registers);
      EXPECT_EQ(SelectBatchKernels(isa).vector_registers, isa == BatchIsa::kAvx512 ? 32 : 16);
    }
  }
}

}  // namespace
}  // namespace hexgait

namespace hexgait {
namespace {

// A creature whose program never moves its legs settles and lies still. Marked as fallen from
// the start (tilt limit below zero), early stop must end its run about one gait cycle in, with
// the distance it would have had at the end, and the batched path must stop at the same step.
// The wedge standing still really is at rest. (The hexapod is not: on its soft-sideways legs it
// creeps, below the kinetic-energy threshold, 0.0037 length units between t = 150 and 300, so
// early stop would change its distance by that much.)
TEST(EarlyStop, StopsACreatureAtRestWithoutChangingItsDistance) {
  CreatureModel model = LoadCreatureOrDefault("wedge");
  model.physics.fall_tilt_degrees = -1;
  MotorProgram program = LoadMotorProgramOrDefault("", model, "wedge");
  for (LegPosition& p : program.positions) p.foot_offset.setZero();
  const Genome genome(MakeGenomeLayout(model, program, false));
  RunOptions options;
  options.duration = 300;
  const RunResult full = EvaluateGenome(model, program, genome, options);
  options.early_stop = true;
  const RunResult early = EvaluateGenome(model, program, genome, options);
  EXPECT_FALSE(full.stopped_early);
  ASSERT_TRUE(early.stopped_early);
  EXPECT_LT(early.end_time, 0.5 * options.duration);
  EXPECT_NEAR(early.distance, full.distance, 1e-6);
  const std::vector<RunResult> batched =
      EvaluateGenomesBatched(model, program, {&genome, &genome}, options);
  ExpectSameResult(early, batched[1], "batched early stop");
  EXPECT_TRUE(batched[1].stopped_early);
}

// On a walking or crawling creature (the usual case: the motor keeps a fallen creature moving)
// early stop must not fire, so the result is unchanged.
TEST(EarlyStop, DoesNotStopACreatureTheMotorStillMoves) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));  // falls at t = 155.9
  RunOptions options;
  options.duration = 400;
  const RunResult full = EvaluateGenome(model, program, genome, options);
  options.early_stop = true;
  const RunResult early = EvaluateGenome(model, program, genome, options);
  ASSERT_TRUE(full.fell) << "pick a genome that falls";
  EXPECT_FALSE(early.stopped_early);
  EXPECT_TRUE(SameBits(early.distance, full.distance));
}

}  // namespace
}  // namespace hexgait

namespace hexgait {
namespace {

// The creature kernel (one creature per set of AVX-512 registers) gives each creature exactly
// its float lane's result: walking, falling, with extreme genomes, and diverging past explicit
// Euler's limit, for every batch size it takes.
void CheckCreatureKernelAgainstFloatLanes(double dt, bool expect_divergence) {
  const CreatureModel model = test::DefaultCreature();
  if (!CreatureSimulation::Available(model)) GTEST_SKIP() << "no AVX-512 on this CPU";
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 60;
  options.dt = dt;
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Genome> genomes(3, Genome(layout));
  for (int i = 0; i < genomes[1].num_genes(); ++i) {
    genomes[1].set_gene(i, -8);
    genomes[2].set_gene(i, 7);
  }
  for (uint64_t k = 0; k < 5; ++k) genomes.push_back(RandomGenome(model, program, 300 + k));
  int fell = 0, diverged = 0;
  for (size_t first = 0; first < genomes.size();) {
    for (int count = 1; count <= kCreatureKernelMaxBatch && first < genomes.size(); ++count) {
      std::vector<const Genome*> batch;
      for (size_t i = first; i < std::min(genomes.size(), first + count); ++i) {
        batch.push_back(&genomes[i]);
      }
      first += batch.size();
      const int n = static_cast<int>(batch.size());
      SCOPED_TRACE("batch of " + std::to_string(n));
      const auto lanes = EvaluateGenomesBatched(model, program, batch, options, BatchLanesFor(n),
                                                BatchIsa::kAuto, Precision::kFloat);
      const auto creatures = EvaluateGenomesWithCreatureKernel(model, program, batch, options);
      const auto automatic = EvaluateGenomesBatched(model, program, batch, options, 0,
                                                    BatchIsa::kAuto, Precision::kFloat);
      for (int i = 0; i < n; ++i) {
        ExpectSameResult(lanes[i], creatures[i], "creature kernel");
        ExpectSameResult(lanes[i], automatic[i], "automatic choice");
        fell += lanes[i].fell;
        diverged += lanes[i].diverged;
      }
    }
  }
  EXPECT_GT(fell, 0) << "some creature should fall, or the comparison proves little";
  if (expect_divergence) {
    EXPECT_GT(diverged, 0) << "some creature should diverge at this step";
  }
}

TEST(CreatureKernel, SameResultsAsFloatLanes) {
  CheckCreatureKernelAgainstFloatLanes(kPaperTimeStep, false);
}

TEST(CreatureKernel, SameResultsAsFloatLanesIncludingDivergence) {
  CheckCreatureKernelAgainstFloatLanes(0.011, true);
}

// The whole state, rest lengths included, after 15 time units of walking and turning legs.
TEST(CreatureKernel, SameStateAsFloatLanesBitForBit) {
  const CreatureModel model = test::DefaultCreature();
  if (!CreatureSimulation::Available(model)) GTEST_SKIP() << "no AVX-512 on this CPU";
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  std::vector<Genome> genomes;
  for (uint64_t k = 0; k < 3; ++k) genomes.push_back(RandomGenome(model, program, 400 + k));
  const std::vector<const Genome*> batch = {&genomes[0], &genomes[1], &genomes[2]};
  CreatureSimulation creatures(model, program, PerturbedRestLengths(model, program, batch),
                               kPaperTimeStep);
  BatchSimulation<float> lanes(model, program, PerturbedRestLengths(model, program, batch),
                               kPaperTimeStep, 4);
  creatures.Advance(6000);
  lanes.Advance(6000);
  SimState a = MakeRestState(model), b = MakeRestState(model);
  for (int c = 0; c < 3; ++c) {
    creatures.Extract(c, a);
    lanes.Extract(c, b);
    EXPECT_EQ(a.step, b.step);
    EXPECT_TRUE(SameBits(a.time, b.time));
    for (int i = 0; i < model.num_particles(); ++i) {
      for (const auto q : {&SimState::x, &SimState::y, &SimState::z, &SimState::vx, &SimState::vy,
                           &SimState::vz}) {
        ASSERT_TRUE(SameBits((a.*q)[i], (b.*q)[i])) << "creature " << c << " particle " << i;
      }
    }
    for (int s = 0; s < model.num_springs(); ++s) {
      ASSERT_TRUE(SameBits(a.rest_length[s], b.rest_length[s])) << "spring " << s;
    }
  }
}

// The controller writes the same rest lengths lane-interleaved and creature-major, step by
// step, with the program's transitions and with instant ones.
TEST(CreatureKernel, ControllerLayoutsAgreeStepByStep) {
  const CreatureModel model = test::DefaultCreature();
  for (double transition : {-1.0, 0.0}) {
    MotorProgram program = LoadMotorProgramOrDefault("", model);
    if (transition >= 0) program.transition_time = transition;
    SCOPED_TRACE("transition time " + std::to_string(program.transition_time));
    std::vector<RestLengthTable> tables;
    for (uint64_t k = 0; k < 3; ++k) {
      tables.push_back(PerturbedRestLengths(model, program, RandomGenome(model, program, k)));
    }
    const int ns = model.num_springs(), pitch = kCreatureKernelSprings, w = 3;
    BatchMotorController interleaved(model, program, tables, kPaperTimeStep);
    BatchMotorController creature_major(model, program, tables, kPaperTimeStep, pitch);
    std::vector<float> a(static_cast<size_t>(ns) * w), b(static_cast<size_t>(pitch) * w, 0.0f);
    for (int s = 0; s < ns; ++s) {
      for (int l = 0; l < w; ++l) {
        a[s * w + l] = b[l * pitch + s] = static_cast<float>(model.rest_length[s]);
      }
    }
    for (long long k = 0; k < 6000; ++k) {
      interleaved.Update(k, a.data());
      creature_major.Update(k, b.data());
      for (int s = 0; s < ns; ++s) {
        for (int l = 0; l < w; ++l) {
          ASSERT_EQ(a[s * w + l], b[l * pitch + s]) << "step " << k << " spring " << s;
        }
      }
    }
    int changed = 0;
    for (int s = 0; s < ns; ++s) changed += a[s * w] != static_cast<float>(model.rest_length[s]);
    EXPECT_GT(changed, 0) << "the legs should have moved";
  }
}

}  // namespace
}  // namespace hexgait
