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

#include "sim/batch_kernel_args.h"
#include "simd/isa.h"

namespace hexgait {

// Runs the peak-throughput loop of `isa` (independent vector multiplies and adds) for
// `iterations`; it performs PeakLoopFlops(isa) flops per iteration. `m` and `a` should be 1 and
// 0, passed at run time so the compiler cannot fold them.
double RunPeakLoop(BatchIsa isa, long long iterations, double m, double a,
                   Precision precision = Precision::kDouble);
int PeakLoopFlops(BatchIsa isa, Precision precision = Precision::kDouble);

// Runs `iterations` of 8 independent vector square roots and 8 divisions (each over
// NativeBatchLanes(isa, precision) lanes): the throughput floor of the kernel's slowest
// operations.
double RunSqrtDivLoop(BatchIsa isa, long long iterations, double seed,
                      Precision precision = Precision::kDouble);

// One explicit Euler step of `lanes` creatures of type T (double or float); `lanes` must be one
// of kBatchLaneCounts.
template <class T>
BatchStepFnT<T> SelectBatchStepT(int lanes, BatchIsa isa = BatchIsa::kAuto);
inline BatchStepFn SelectBatchStep(int lanes, BatchIsa isa = BatchIsa::kAuto) {
  return SelectBatchStepT<double>(lanes, isa);
}

}  // namespace hexgait
