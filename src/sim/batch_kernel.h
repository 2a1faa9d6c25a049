// The batched explicit-Euler step: a population of creatures with one topology advanced in
// lock-step, one creature per SIMD lane. Each value is stored `lanes` wide, one per creature
// (sim/batch_state.h), so every per-particle or per-spring operation is one vector instruction
// across the creatures.
//
// The kernel is compiled once per instruction set (generic x86-64, AVX2, AVX-512) from one
// source (batch_kernel_impl.h) and chosen at run time from what the CPU supports, so the
// project is never built with -march=native. Every lane performs exactly the scalar
// EulerStepper's operations in the same order (see docs/model.md, "Batched simulation"), and
// IEEE add, multiply, divide and square root are correctly rounded in SIMD too, so each lane's
// result is bit-identical to the scalar path on every instruction set.
#pragma once

#include <string>

#include "sim/batch_kernel_args.h"

namespace hexgait {

// Lane counts with a compiled kernel.
inline constexpr int kBatchLaneCounts[] = {1, 2, 4, 8, 16};
inline constexpr int kMaxBatchLanes = 16;

// Smallest compiled lane count that holds `creatures` (at most kMaxBatchLanes).
int BatchLanesFor(int creatures);

// Instruction sets, best last. kAuto picks the best this CPU supports.
enum class BatchIsa { kAuto, kGeneric, kAvx2, kAvx512 };
std::string BatchIsaName(BatchIsa isa);
// The instruction set kAuto resolves to on this CPU.
BatchIsa BestBatchIsa();
bool BatchIsaSupported(BatchIsa isa);
// Doubles per vector register: 2 (x86-64 SSE2), 4 (AVX2), 8 (AVX-512). A batch up to this wide
// costs about the same per step as a batch of one.
int NativeBatchLanes(BatchIsa isa = BatchIsa::kAuto);

// Runs the peak-throughput loop of `isa` (independent vector multiplies and adds) for
// `iterations`; it performs PeakLoopFlops(isa) flops per iteration. `m` and `a` should be 1 and
// 0, passed at run time so the compiler cannot fold them.
double RunPeakLoop(BatchIsa isa, long long iterations, double m, double a);
inline int PeakLoopFlops(BatchIsa isa) {
  return 16 * NativeBatchLanes(isa);
}

// Runs `iterations` of 8 independent vector square roots and 8 divisions (each over
// NativeBatchLanes(isa) lanes): the throughput floor of the kernel's slowest operations.
double RunSqrtDivLoop(BatchIsa isa, long long iterations, double seed);

// One explicit Euler step of `lanes` creatures; `lanes` must be one of kBatchLaneCounts.
BatchStepFn SelectBatchStep(int lanes, BatchIsa isa = BatchIsa::kAuto);

}  // namespace hexgait
