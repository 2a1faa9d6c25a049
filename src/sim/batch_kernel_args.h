// The batched kernel's arguments, as plain pointers: the per-instruction-set translation units
// include only this header, so they instantiate no shared inline code (batch_kernel_impl.h).
#pragma once

namespace hexgait {

// T is the lanes' number type: double (bit-identical to the scalar path) or float (twice the
// lanes per register; docs/model.md, "Float lanes").
template <class T>
struct BatchKernelArgsT {
  int num_particles = 0;
  int num_springs = 0;
  const int* spring_a = nullptr;  // per spring
  const int* spring_b = nullptr;
  const T* stiffness = nullptr;
  const T* damping = nullptr;
  const T* mass = nullptr;  // per particle
  const T* inv_mass = nullptr;
  T gravity = 0, ground_stiffness = 0, ground_damping = 0, friction = 0;
  T slip_velocity2 = 0;  // slip_velocity squared, as the scalar kernel computes it
  T dt = 0;
  // Lane-interleaved state: particle i's block of 6 * lanes values holds x, y, z, vx, vy, vz,
  // each `lanes` wide ([(i * 6 + component) * lanes + lane]); one base pointer reaches every
  // quantity of a particle, which keeps the kernel's registers for arithmetic.
  T* state = nullptr;
  const T* rest_length = nullptr;  // [spring * lanes + lane]
  // Each particle's springs in spring order (the order the scalar kernel sums its forces in):
  // particle i's entries are incident[incident_start[i] .. incident_start[i + 1]), each
  // 2 * spring + (1 if the particle is the spring's b end, which subtracts, else 0).
  const int* incident_start = nullptr;
  const int* incident = nullptr;
  T* spring_force = nullptr;  // scratch: [(spring * 3 + component) * lanes + lane]
};

using BatchKernelArgs = BatchKernelArgsT<double>;
using BatchKernelArgsF = BatchKernelArgsT<float>;

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

// What one instruction set's translation unit (batch_kernel_{generic,avx2,avx512}.cc) exports.
struct BatchIsaKernels {
  const BatchStepFn* step;  // index j: the kernel for kBatchLaneCounts[j] lanes
  const BatchStepFnF* step_float;
  LaneInterpolateFnT<double> interpolate;
  LaneInterpolateFnT<float> interpolate_float;
  SpanInterpolateFnT<double> interpolate_span;
  SpanInterpolateFnT<float> interpolate_span_float;
  TransitionFractionsFn transition_fractions;
  double (*peak_loop)(long long iterations, double m, double a);
  double (*peak_loop_float)(long long iterations, float m, float a);
  double (*sqrt_div_loop)(long long iterations, double seed);
  double (*sqrt_div_loop_float)(long long iterations, float seed);
};

}  // namespace hexgait
