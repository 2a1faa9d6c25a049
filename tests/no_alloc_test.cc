// The step loops never allocate: a counting global operator new (this file replaces it for the
// whole test binary; it only counts while a test asks it to).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "ga/genome.h"
#include "motor/batch_controller.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/batch_kernel.h"
#include "sim/batch_state.h"
#include "sim/integrator.h"
#include "sim/run.h"
#include "test_util.h"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

// Every plain and nothrow form is replaced, so each allocation and its release pair up (the
// aligned forms, used by the batched state's allocator, are left to the library in pairs).
// GCC, inlining these, pairs free() with operator new and warns of a mismatch; the pairing is
// right (operator new allocates with malloc), so that warning is off for this file.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new(std::size_t size) {
  if (void* p = operator new(size, std::nothrow)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return operator new(size, std::nothrow);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace hexgait {
namespace {

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

  allocations = 0;
  counting = true;
  for (long long k = 0; k < 2000; ++k) {  // several instructions and transitions
    batch_controller.Update(k, batch.rest_length.data());
    step(args);
    controller.Update(k, state.rest_length.data());
    EulerStepper::Step(model, state, kPaperTimeStep);
  }
  ExtractLane(batch, 2, lane);
  counting = false;
  EXPECT_EQ(allocations.load(), 0);

  // The counter works: an allocation while counting is seen.
  counting = true;
  static std::vector<double>* volatile probe;  // volatile: the allocation cannot be elided
  probe = new std::vector<double>(8);
  counting = false;
  delete probe;
  EXPECT_GE(allocations.load(), 1);
}

}  // namespace
}  // namespace hexgait
