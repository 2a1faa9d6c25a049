// The batched kernel's arguments, as plain pointers: the per-instruction-set translation units
// include only this header, so they instantiate no shared inline code (batch_kernel_impl.h).
#pragma once

#include "simd/kernel_table.h"

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
  // 2 * (the spring's offset in spring_force, 3 * lanes * spring) + (1 if the particle is the
  // spring's b end, which subtracts, else 0): the kernel's gather is one shift from it.
  const int* incident_start = nullptr;
  const int* incident = nullptr;
  T* spring_force = nullptr;  // scratch: [(spring * 3 + component) * lanes + lane]
};

using BatchKernelArgs = BatchKernelArgsT<double>;
using BatchKernelArgsF = BatchKernelArgsT<float>;

}  // namespace hexgait
