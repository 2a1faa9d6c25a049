#include "bench/free_flight.h"

#include <cmath>

namespace hexgait {

FreeFlight MakeFreeFlight(const CreatureModel& creature, bool spring_damping) {
  FreeFlight f{creature, {}, 0};
  f.model.physics.ground_stiffness = 0;
  f.model.physics.ground_damping = 0;
  f.model.physics.friction = 0;
  if (!spring_damping) f.model.damping.assign(f.model.num_springs(), 0.0);
  f.initial = MakeRestState(f.model);
  for (int i = 0; i < f.initial.num_particles(); ++i) {
    f.initial.z[i] += 5.0;
    f.initial.vx[i] = 0.05 * std::sin(1.7 * i);
    f.initial.vy[i] = 0.05 * std::cos(2.3 * i);
    f.initial.vz[i] = 0.05 * std::sin(0.9 * i + 1);
  }
  for (int k = 0; k < f.model.num_springs(); ++k) {
    f.initial.rest_length[k] *= 1.0 + 0.05 * std::sin(1.0 + k);
  }
  f.vibration_energy = TotalEnergy(f.model, f.initial) - GravityEnergy(f.model, f.initial);
  return f;
}

double GravityEnergy(const CreatureModel& model, const SimState& state) {
  double e = 0;
  for (int i = 0; i < state.num_particles(); ++i) {
    e += model.mass[i] * model.physics.gravity * state.z[i];
  }
  return e;
}

}  // namespace hexgait
