#include "sim/state.h"

#include <Eigen/Geometry>
#include <cmath>

#include "sim/body_frame.h"

namespace hexgait {
namespace {

// BodyFrame's operations on one double: std::fmin is the one-creature path's minimum.
struct OneStateFrameOps {
  using V = double;
  static V Splat(double value) { return value; }
  static V Sqrt(V v) { return std::sqrt(v); }
  static V SelectPositive(V s, V a, V b) { return s > 0 ? a : b; }
  static V Min(V a, V b) { return std::fmin(a, b); }
};

auto StatePositions(const SimState& s) {
  return [&s](int i) { return Point<double>{s.x[i], s.y[i], s.z[i]}; };
}

}  // namespace

SimState MakeRestState(const CreatureModel& model) {
  const int n = model.num_particles();
  SimState s;
  s.x.resize(n);
  s.y.resize(n);
  s.z.resize(n);
  s.vx.assign(n, 0.0);
  s.vy.assign(n, 0.0);
  s.vz.assign(n, 0.0);
  s.fx.assign(n, 0.0);
  s.fy.assign(n, 0.0);
  s.fz.assign(n, 0.0);
  s.spring_fx.assign(model.num_springs(), 0.0);
  s.spring_fy.assign(model.num_springs(), 0.0);
  s.spring_fz.assign(model.num_springs(), 0.0);
  for (int i = 0; i < n; ++i) {
    s.x[i] = model.rest_position[i].x();
    s.y[i] = model.rest_position[i].y();
    s.z[i] = model.rest_position[i].z();
  }
  s.rest_length = model.rest_length;
  return s;
}

Eigen::Vector3d BodyCentre(const CreatureModel& model, const SimState& state) {
  const Point<double> c =
      BodyFrame<OneStateFrameOps>::Mean(model.body_particles, StatePositions(state));
  return {c.x, c.y, c.z};
}

double LowestBodyHeight(const CreatureModel& model, const SimState& state) {
  return BodyFrame<OneStateFrameOps>::Lowest(model, StatePositions(state));
}

void BodyAxes(const CreatureModel& model, const SimState& state, Eigen::Vector3d* forward,
              Eigen::Vector3d* left, Eigen::Vector3d* up) {
  Point<double> f, l, u;
  BodyFrame<OneStateFrameOps>::Axes(model, StatePositions(state), f, l, u);
  if (forward) *forward = {f.x, f.y, f.z};
  if (left) *left = {l.x, l.y, l.z};
  if (up) *up = {u.x, u.y, u.z};
}

double TiltDegrees(double up_z) {
  const double c = std::fmax(-1.0, std::fmin(1.0, up_z));
  return std::acos(c) * 180.0 / M_PI;
}

double BodyTiltDegrees(const CreatureModel& model, const SimState& state) {
  Eigen::Vector3d up;
  BodyAxes(model, state, nullptr, nullptr, &up);
  return TiltDegrees(up.z());
}

void BodyPitchRollDegrees(const CreatureModel& model, const SimState& state, double* pitch,
                          double* roll) {
  Eigen::Vector3d forward, left, up;
  BodyAxes(model, state, &forward, &left, &up);
  const double f = std::fmax(-1.0, std::fmin(1.0, forward.z()));
  *pitch = std::asin(f) * 180.0 / M_PI;
  *roll = std::atan2(left.z(), up.z()) * 180.0 / M_PI;
}

double KineticEnergy(const CreatureModel& model, const SimState& s) {
  double e = 0;
  for (int i = 0; i < s.num_particles(); ++i) {
    e += 0.5 * model.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
  }
  return e;
}

double TotalEnergy(const CreatureModel& model, const SimState& s) {
  double e = KineticEnergy(model, s);
  const PhysicsConstants& phys = model.physics;
  for (int i = 0; i < s.num_particles(); ++i) {
    e += model.mass[i] * phys.gravity * s.z[i];
    if (phys.gravity_x != 0) e -= model.mass[i] * phys.gravity_x * s.x[i];  // on a slope
    if (s.z[i] < 0) e += 0.5 * phys.ground_stiffness * s.z[i] * s.z[i];
  }
  for (int k = 0; k < model.num_springs(); ++k) {
    const int a = model.spring_a[k], b = model.spring_b[k];
    const double stretch = (s.position(b) - s.position(a)).norm() - s.rest_length[k];
    e += 0.5 * model.stiffness[k] * stretch * stretch;
  }
  return e;
}

void PushBody(const CreatureModel& model, double impulse_y, SimState& state) {
  double body_mass = 0;
  for (int i : model.body_particles) body_mass += model.mass[i];
  const double dv = impulse_y / body_mass;
  for (int i : model.body_particles) state.vy[i] += dv;
}

}  // namespace hexgait
