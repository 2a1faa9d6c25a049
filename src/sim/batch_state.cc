#include "sim/batch_state.h"

namespace hexgait {

namespace {
template <class T>
std::vector<T> Rounded(const std::vector<double>& v) {
  return std::vector<T>(v.begin(), v.end());
}
}  // namespace

template <class T>
BatchStateT<T> MakeBatchStateT(const CreatureModel& model, const SimState& state, int lanes) {
  BatchStateT<T> b;
  b.lanes = lanes;
  b.state.assign(static_cast<size_t>(model.num_particles()) * 6 * lanes, T(0));
  b.spring_force.assign(static_cast<size_t>(model.num_springs()) * 3 * lanes, T(0));
  b.rest_length.assign(static_cast<size_t>(model.num_springs()) * lanes, T(0));
  b.stiffness = Rounded<T>(model.stiffness);
  b.damping = Rounded<T>(model.damping);
  b.mass = Rounded<T>(model.mass);
  b.inv_mass = Rounded<T>(model.inv_mass);
  b.incident_start.push_back(0);
  for (int i = 0; i < model.num_particles(); ++i) {
    for (int k = 0; k < model.num_springs(); ++k) {
      const int force = 3 * lanes * k;  // where spring k's force starts in spring_force
      if (model.spring_a[k] == i) b.incident.push_back(2 * force);
      if (model.spring_b[k] == i) b.incident.push_back(2 * force + 1);
    }
    b.incident_start.push_back(static_cast<int>(b.incident.size()));
  }
  for (int lane = 0; lane < lanes; ++lane) InsertLane(state, lane, b);
  b.step = state.step;
  b.time = state.time;
  return b;
}

template <class T>
void InsertLane(const SimState& s, int lane, BatchStateT<T>& b) {
  const std::vector<double>* quantities[6] = {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz};
  for (int i = 0; i < s.num_particles(); ++i) {
    for (int c = 0; c < 6; ++c) b.at(i, c, lane) = static_cast<T>((*quantities[c])[i]);
  }
  for (size_t k = 0; k < s.rest_length.size(); ++k) {
    b.rest_length[k * b.lanes + lane] = static_cast<T>(s.rest_length[k]);
  }
}

template <class T>
void ExtractLane(const BatchStateT<T>& b, int lane, SimState& s) {
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

template <class T>
BatchKernelArgsT<T> MakeBatchKernelArgs(const CreatureModel& model, BatchStateT<T>& s, double dt) {
  BatchKernelArgsT<T> a;
  a.num_particles = model.num_particles();
  a.num_springs = model.num_springs();
  a.spring_a = model.spring_a.data();
  a.spring_b = model.spring_b.data();
  a.stiffness = s.stiffness.data();
  a.damping = s.damping.data();
  a.mass = s.mass.data();
  a.inv_mass = s.inv_mass.data();
  const PhysicsConstants& phys = model.physics;
  a.gravity = static_cast<T>(phys.gravity);
  a.ground_stiffness = static_cast<T>(phys.ground_stiffness);
  a.ground_damping = static_cast<T>(phys.ground_damping);
  a.friction = static_cast<T>(phys.friction);
  // Squared in double, then rounded: as the scalar kernel for double.
  a.slip_velocity2 = static_cast<T>(phys.slip_velocity * phys.slip_velocity);
  a.dt = static_cast<T>(dt);
  a.state = s.state.data();
  a.rest_length = s.rest_length.data();
  a.incident_start = s.incident_start.data();
  a.incident = s.incident.data();
  a.spring_force = s.spring_force.data();
  return a;
}

#define HEXGAIT_INSTANTIATE(T)                                                               \
  template BatchStateT<T> MakeBatchStateT<T>(const CreatureModel&, const SimState&, int);    \
  template void InsertLane<T>(const SimState&, int, BatchStateT<T>&);                        \
  template void ExtractLane<T>(const BatchStateT<T>&, int, SimState&);                       \
  template BatchKernelArgsT<T> MakeBatchKernelArgs<T>(const CreatureModel&, BatchStateT<T>&, \
                                                      double);
HEXGAIT_INSTANTIATE(double)
HEXGAIT_INSTANTIATE(float)
#undef HEXGAIT_INSTANTIATE

}  // namespace hexgait
