// No integrator allocates inside Step(): a counting malloc wraps glibc's for this test binary
// only (Eigen and operator new both allocate through malloc). Not built with the sanitizers,
// which replace malloc themselves.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/batch_controller.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/batch_evaluate.h"
#include "sim/batch_kernel.h"
#include "sim/batch_state.h"
#include "sim/creature_simulation.h"
#include "sim/step_loop.h"
#include "sim/steppers.h"
#include "test_util.h"

extern "C" void* __libc_malloc(size_t size);  // glibc's own allocator

namespace {
std::atomic<long> g_mallocs{0};
}

extern "C" void* malloc(size_t size) {
  g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}

namespace hexgait {
namespace {

TEST(NoAllocation, EveryStepperWithTheMotorRunning) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  for (IntegratorKind kind : AllIntegrators()) {
    const double dt = 0.0025;
    MotorController controller(model, program, PerturbedRestLengths(model, program, genome), dt);
    SimState state = MakeRestState(model);
    long allocations = -1;
    WithStepper(kind, model, [&](auto& stepper) {
      stepper.Begin(model, state);
      for (long long k = 0; k < 10; ++k) {  // warm up: nothing lazily sized later
        controller.Update(k, state.rest_length.data());
        stepper.Step(model, state, dt);
      }
      const long before = g_mallocs.load();
      // 20 time units: the first instructions and transitions, feet in contact.
      for (long long k = 10; k < 8000; ++k) {
        controller.Update(k, state.rest_length.data());
        stepper.Step(model, state, dt);
      }
      allocations = g_mallocs.load() - before;
    });
    EXPECT_EQ(allocations, 0) << IntegratorName(kind);
  }
  // The counter works (the test would pass trivially otherwise).
  const long before = g_mallocs.load();
  std::vector<double>* v = new std::vector<double>(100);
  delete v;
  EXPECT_GE(g_mallocs.load() - before, 2);
}

}  // namespace
// The batched lanes (the GA's path) and the scalar Euler loop beside them: no allocation either.
TEST(NoAllocation, BatchedAndScalarStepsDoNotAllocate) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const RestLengthTable table = GeometricRestLengths(model, program);
  BatchMotorController batch_controller(model, program, {table, table, table, table},
                                        kPaperTimeStep);
  BatchState batch = MakeBatchState(model, MakeRestState(model), 4);
  const BatchKernelArgs args = MakeBatchKernelArgs(model, batch, kPaperTimeStep);
  const BatchStepFn step = SelectBatchStep(4);
  MotorController controller(model, program, table, kPaperTimeStep);
  SimState state = MakeRestState(model);
  SimState lane = MakeRestState(model);
  EulerStepper euler(model);
  euler.Begin(model, state);
  const long before = g_mallocs.load();
  for (long long k = 0; k < 2000; ++k) {  // several instructions and transitions
    batch_controller.Update(k, batch.rest_length.data());
    step(args);
    controller.Update(k, state.rest_length.data());
    euler.Step(model, state, kPaperTimeStep);
  }
  ExtractLane(batch, 2, lane);
  EXPECT_EQ(g_mallocs.load() - before, 0);
}

// Advancing and reading a simulation the way the GA's evaluation loop does: no allocation.
template <class Sim>
void ExpectAdvancingDoesNotAllocate(const CreatureModel& model, Sim& sim) {
  SimState lane = MakeRestState(model);
  const long before = g_mallocs.load();
  for (int k = 0; k < 50; ++k) {
    sim.Advance(40);
    sim.Extract(1, lane);
  }
  EXPECT_EQ(g_mallocs.load() - before, 0);
}

// Float lanes, through BatchSimulation as the GA runs them.
TEST(NoAllocation, FloatLanesDoNotAllocate) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  BatchSimulation<float> sim(model, program,
                             PerturbedRestLengths(model, program, {&genome, &genome, &genome}),
                             kPaperTimeStep);
  ExpectAdvancingDoesNotAllocate(model, sim);
}

TEST(NoAllocation, CreatureKernelDoesNotAllocate) {
  const CreatureModel model = test::DefaultCreature();
  if (!CreatureSimulation::Available(model)) GTEST_SKIP() << "no AVX-512 on this CPU";
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const Genome genome(MakeGenomeLayout(model, program, false));
  CreatureSimulation sim(model, program,
                         PerturbedRestLengths(model, program, {&genome, &genome, &genome}),
                         kPaperTimeStep);
  ExpectAdvancingDoesNotAllocate(model, sim);
}

}  // namespace hexgait
