// The explicit steppers' loops, one axis at a time: Axes unpacks a state's position, velocity
// and force arrays once, and each loop below runs over one axis's arrays with restrict-qualified
// parameters (so the compiler may vectorise it). A stepper composes these instead of listing
// nine pointers of its own; each loop's arithmetic is exactly the update its comment names.
#pragma once

#include <array>

#include "sim/state.h"

namespace hexgait {

// One axis (x, y or z) of every particle.
struct Axis {
  double* position;
  double* velocity;
  const double* force;  // valid after ComputeForces
};

inline std::array<Axis, 3> Axes(SimState& s) {
  return {Axis{s.x.data(), s.vx.data(), s.fx.data()}, Axis{s.y.data(), s.vy.data(), s.fy.data()},
          Axis{s.z.data(), s.vz.data(), s.fz.data()}};
}

// to[i] += c * from[i]: a drift (position from velocity) or a kick (velocity from acceleration).
inline void AddScaled(int n, double c, const double* __restrict from, double* __restrict to) {
  for (int i = 0; i < n; ++i) to[i] += c * from[i];
}

// out[i] = base[i] + c * from[i]: a predicted or stage value.
inline void ScaledSum(int n, const double* __restrict base, double c, const double* __restrict from,
                      double* __restrict out) {
  for (int i = 0; i < n; ++i) out[i] = base[i] + c * from[i];
}

// acceleration[i] = force[i] * inv_mass[i]
inline void Accelerations(int n, const double* __restrict inv_mass, const double* __restrict force,
                          double* __restrict acceleration) {
  for (int i = 0; i < n; ++i) acceleration[i] = force[i] * inv_mass[i];
}

// velocity[i] += (dt * inv_mass[i]) * force[i]: a whole-step kick by the force.
inline void KickByForce(int n, double dt, const double* __restrict inv_mass,
                        const double* __restrict force, double* __restrict velocity) {
  for (int i = 0; i < n; ++i) velocity[i] += (dt * inv_mass[i]) * force[i];
}

}  // namespace hexgait
