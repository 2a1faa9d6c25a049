// What one instruction set's translation unit exports: the batched step kernels, the motor
// controller's vectorised interpolations and the benchmark loops, as plain function pointers.
// Below both sim and motor, which share it. No includes: the per-instruction-set translation
// units include this, and must instantiate no shared inline code (sim/batch_kernel_impl.h).
#pragma once

namespace hexgait {

template <class T>
struct BatchKernelArgsT;  // sim/batch_kernel_args.h

template <class T>
using BatchStepFnT = void (*)(const BatchKernelArgsT<T>& args);
using BatchStepFn = BatchStepFnT<double>;
using BatchStepFnF = BatchStepFnT<float>;

// out[e] = from[e] + f change[e] for e < count, computed in double and rounded to T: the
// motor controller's rest-length transitions (change = to - from), all lanes of a spring at once.
template <class T>
using LaneInterpolateFnT = void (*)(const double* from, const double* change, double f, T* out,
                                    int count);

// out[e] = from[e] + fraction[e] change[e] for e < count, in double, rounded to T: one lane's
// springs at once, each with its own fraction.
template <class T>
using SpanInterpolateFnT = void (*)(const double* from, const double* change,
                                    const double* fraction, T* out, int count);
// fraction[e] = how far a transition that started at step start[e] and lasts `steps` steps is
// at step `step` (MotorController::Move's f: 1 once done), for e < count.
using TransitionFractionsFn = void (*)(const double* start, double step, double steps,
                                       double* fraction, int count);

// The lane-clocked controller's whole step (motor/lane_clocked_controller.h) in one call: each
// leg's fraction in every lane, as TransitionFractionsFn computes it, into
// fraction[leg * lanes + lane] (`legs` legs), then for every leg spring k and lane,
// out[springs[k] * lanes + lane] = from + fraction[leg_of[k] * lanes + lane] change at the same
// index, in double and rounded to T: SpanInterpolateFnT's arithmetic, without a call per spring.
struct LegMoveArgs {
  const double* start;  // [leg * lanes + lane]: the batch's step the transition started at
  double step, steps;
  double* fraction;  // [leg * lanes + lane], written
  int legs;
  const double* from;  // [spring * lanes + lane]
  const double* change;
  const int* springs;  // the leg springs, and each one's leg
  const int* leg_of;
  int count;
  int lanes;
};
template <class T>
using LegMoveFnT = void (*)(const LegMoveArgs& args, T* out);

// What one instruction set's translation unit (batch_kernel_{generic,avx2,avx512}.cc) exports.
struct BatchIsaKernels {
  int vector_registers;     // 32 with AVX-512, 16 with SSE2 and AVX2
  const BatchStepFn* step;  // index j: the kernel for kBatchLaneCounts[j] lanes
  const BatchStepFnF* step_float;
  LaneInterpolateFnT<double> interpolate;
  LaneInterpolateFnT<float> interpolate_float;
  SpanInterpolateFnT<double> interpolate_span;
  SpanInterpolateFnT<float> interpolate_span_float;
  TransitionFractionsFn transition_fractions;
  LegMoveFnT<double> move_legs;
  LegMoveFnT<float> move_legs_float;
  double (*peak_loop)(long long iterations, double m, double a);
  double (*peak_loop_float)(long long iterations, float m, float a);
  int peak_loop_chains;  // independent multiply chains in peak_loop, and as many add chains
  double (*sqrt_div_loop)(long long iterations, double seed);
  double (*sqrt_div_loop_float)(long long iterations, float seed);
};

}  // namespace hexgait
