// The batched kernel's arguments, as plain pointers: the per-instruction-set translation units
// include only this header, so they instantiate no shared inline code (batch_kernel_impl.h).
#pragma once

namespace hexgait {

struct BatchKernelArgs {
  int num_particles = 0;
  int num_springs = 0;
  const int* spring_a = nullptr;  // per spring
  const int* spring_b = nullptr;
  const double* stiffness = nullptr;
  const double* damping = nullptr;
  const double* mass = nullptr;  // per particle
  const double* inv_mass = nullptr;
  double gravity = 0, ground_stiffness = 0, ground_damping = 0, friction = 0;
  double slip_velocity2 = 0;  // slip_velocity squared, as the scalar kernel computes it
  double dt = 0;
  // Lane-interleaved state: particle i's block of 6 * lanes values holds x, y, z, vx, vy, vz,
  // each `lanes` wide ([(i * 6 + component) * lanes + lane]); one base pointer reaches every
  // quantity of a particle, which keeps the kernel's registers for arithmetic.
  double* state = nullptr;
  const double* rest_length = nullptr;  // [spring * lanes + lane]
  double* force = nullptr;              // scratch: [(i * 3 + component) * lanes + lane]
};

using BatchStepFn = void (*)(const BatchKernelArgs& args);

}  // namespace hexgait
