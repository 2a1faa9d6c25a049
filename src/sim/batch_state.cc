#include "sim/batch_state.h"

namespace hexgait {

BatchState MakeBatchState(const CreatureModel& model, const SimState& state, int lanes) {
  BatchState b;
  b.lanes = lanes;
  b.state.assign(static_cast<size_t>(model.num_particles()) * 6 * lanes, 0.0);
  b.force.assign(static_cast<size_t>(model.num_particles()) * 3 * lanes, 0.0);
  b.rest_length.assign(static_cast<size_t>(model.num_springs()) * lanes, 0.0);
  for (int lane = 0; lane < lanes; ++lane) InsertLane(state, lane, b);
  b.step = state.step;
  b.time = state.time;
  return b;
}

void InsertLane(const SimState& s, int lane, BatchState& b) {
  const std::vector<double>* quantities[6] = {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz};
  for (int i = 0; i < s.num_particles(); ++i) {
    for (int c = 0; c < 6; ++c) b.at(i, c, lane) = (*quantities[c])[i];
  }
  for (size_t k = 0; k < s.rest_length.size(); ++k) {
    b.rest_length[k * b.lanes + lane] = s.rest_length[k];
  }
}

void ExtractLane(const BatchState& b, int lane, SimState& s) {
  std::vector<double>* quantities[6] = {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz};
  for (int i = 0; i < s.num_particles(); ++i) {
    for (int c = 0; c < 6; ++c) (*quantities[c])[i] = b.at(i, c, lane);
  }
  for (size_t k = 0; k < s.rest_length.size(); ++k) {
    s.rest_length[k] = b.rest_length[k * b.lanes + lane];
  }
  s.step = b.step;
  s.time = b.time;
}

BatchKernelArgs MakeBatchKernelArgs(const CreatureModel& model, BatchState& s, double dt) {
  BatchKernelArgs a;
  a.num_particles = model.num_particles();
  a.num_springs = model.num_springs();
  a.spring_a = model.spring_a.data();
  a.spring_b = model.spring_b.data();
  a.stiffness = model.stiffness.data();
  a.damping = model.damping.data();
  a.mass = model.mass.data();
  a.inv_mass = model.inv_mass.data();
  const PhysicsConstants& phys = model.physics;
  a.gravity = phys.gravity;
  a.ground_stiffness = phys.ground_stiffness;
  a.ground_damping = phys.ground_damping;
  a.friction = phys.friction;
  a.slip_velocity2 = phys.slip_velocity * phys.slip_velocity;
  a.dt = dt;
  a.state = s.state.data();
  a.rest_length = s.rest_length.data();
  a.force = s.force.data();
  return a;
}

}  // namespace hexgait
