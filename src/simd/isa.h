// The instruction sets the batched kernels are compiled for, which one this CPU runs, and the
// lanes' number type: the platform layer under sim (the batched kernel) and motor (the batch
// controller's interpolations), chosen at run time so the project is never built with
// -march=native.
#pragma once

#include <string>

#include "simd/kernel_table.h"

namespace hexgait {

// The lanes' number type. kDouble is bit-identical to the scalar path and is the default;
// kFloat puts twice the lanes in a register (docs/model.md, "Float lanes").
enum class Precision { kDouble, kFloat };
std::string PrecisionName(Precision precision);  // "double" or "float"
// The inverse of PrecisionName, the one parser of a precision's name (flags, checkpoints, the
// Python module); throws InputError naming the value and the choices.
Precision ParsePrecision(const std::string& name);

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
// Values per vector register: doubles 2 (x86-64 SSE2), 4 (AVX2), 8 (AVX-512); twice as many
// floats. A batch up to this wide costs about the same per step as a batch of one.
int NativeBatchLanes(BatchIsa isa = BatchIsa::kAuto, Precision precision = Precision::kDouble);
// The widest batch that costs no more per creature than one vector (at most kMaxBatchLanes):
// two vectors where the instruction set has 32 vector registers (AVX-512), one where it has 16
// (SSE2, AVX2: a batch of two vectors ran 5-9% slower per creature there; docs/speed.md, "On a
// Zen 3").
int PreferredBatchLanes(BatchIsa isa = BatchIsa::kAuto, Precision precision = Precision::kDouble);

// Everything `isa`'s translation unit exports (kernels, the controller's interpolations, the
// benchmark loops); throws InputError if this CPU lacks `isa`.
const BatchIsaKernels& SelectBatchKernels(BatchIsa isa = BatchIsa::kAuto);

}  // namespace hexgait
