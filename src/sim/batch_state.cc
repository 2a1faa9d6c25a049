#include "sim/batch_state.h"

namespace hexgait {
namespace {

// Lane `lane` of `wide` <- `narrow`, or the reverse.
void Widen(const std::vector<double>& narrow, int lanes, int lane, LaneArray& wide) {
  for (size_t i = 0; i < narrow.size(); ++i) wide[i * lanes + lane] = narrow[i];
}
void Narrow(const LaneArray& wide, int lanes, int lane, std::vector<double>& narrow) {
  for (size_t i = 0; i < narrow.size(); ++i) narrow[i] = wide[i * lanes + lane];
}

}  // namespace

BatchState MakeBatchState(const CreatureModel& model, const SimState& state, int lanes) {
  BatchState b;
  b.lanes = lanes;
  const size_t n = static_cast<size_t>(model.num_particles()) * lanes;
  const size_t ns = static_cast<size_t>(model.num_springs()) * lanes;
  for (LaneArray* a : {&b.x, &b.y, &b.z, &b.vx, &b.vy, &b.vz, &b.fx, &b.fy, &b.fz}) {
    a->assign(n, 0.0);
  }
  for (LaneArray* a : {&b.rest_length, &b.spring_fx, &b.spring_fy, &b.spring_fz}) {
    a->assign(ns, 0.0);
  }
  for (int lane = 0; lane < lanes; ++lane) InsertLane(state, lane, b);
  b.step = state.step;
  b.time = state.time;
  return b;
}

void InsertLane(const SimState& s, int lane, BatchState& b) {
  Widen(s.x, b.lanes, lane, b.x);
  Widen(s.y, b.lanes, lane, b.y);
  Widen(s.z, b.lanes, lane, b.z);
  Widen(s.vx, b.lanes, lane, b.vx);
  Widen(s.vy, b.lanes, lane, b.vy);
  Widen(s.vz, b.lanes, lane, b.vz);
  Widen(s.rest_length, b.lanes, lane, b.rest_length);
}

void ExtractLane(const BatchState& b, int lane, SimState& s) {
  Narrow(b.x, b.lanes, lane, s.x);
  Narrow(b.y, b.lanes, lane, s.y);
  Narrow(b.z, b.lanes, lane, s.z);
  Narrow(b.vx, b.lanes, lane, s.vx);
  Narrow(b.vy, b.lanes, lane, s.vy);
  Narrow(b.vz, b.lanes, lane, s.vz);
  Narrow(b.rest_length, b.lanes, lane, s.rest_length);
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
  a.x = s.x.data();
  a.y = s.y.data();
  a.z = s.z.data();
  a.vx = s.vx.data();
  a.vy = s.vy.data();
  a.vz = s.vz.data();
  a.rest_length = s.rest_length.data();
  a.fx = s.fx.data();
  a.fy = s.fy.data();
  a.fz = s.fz.data();
  a.spring_fx = s.spring_fx.data();
  a.spring_fy = s.spring_fy.data();
  a.spring_fz = s.spring_fz.data();
  return a;
}

}  // namespace hexgait
