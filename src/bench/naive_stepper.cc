#include "bench/naive_stepper.h"

#include <Eigen/Geometry>
#include <cmath>

namespace hexgait {

NaiveState MakeNaiveState(const CreatureModel& model) {
  NaiveState s;
  s.position = model.rest_position;
  s.velocity.assign(model.rest_position.size(), Eigen::Vector3d::Zero());
  s.force.assign(model.rest_position.size(), Eigen::Vector3d::Zero());
  return s;
}

void NaiveEulerStep(const CreatureModel& model, const double* rest_length, NaiveState& s,
                    double dt) {
  const PhysicsConstants& phys = model.physics;
  const size_t n = s.position.size();
  for (size_t i = 0; i < n; ++i) s.force[i] = Eigen::Vector3d(0, 0, -model.mass[i] * phys.gravity);
  for (int k = 0; k < model.num_springs(); ++k) {
    const int a = model.spring_a[k], b = model.spring_b[k];
    const Eigen::Vector3d d = s.position[b] - s.position[a];
    const double length = d.norm();
    const Eigen::Vector3d u = d / length;
    const double rate = (s.velocity[b] - s.velocity[a]).dot(u);
    const Eigen::Vector3d f =
        (model.stiffness[k] * (length - rest_length[k]) + model.damping[k] * rate) * u;
    s.force[a] += f;
    s.force[b] -= f;
  }
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = s.position[i];
    const Eigen::Vector3d& v = s.velocity[i];
    if (p.z() >= 0) continue;
    const double normal = -phys.ground_stiffness * p.z() - phys.ground_damping * v.z();
    if (normal <= 0) continue;
    const Eigen::Vector2d slide = v.head<2>();
    const double speed = std::sqrt(slide.squaredNorm() + phys.slip_velocity * phys.slip_velocity);
    s.force[i].z() += normal;
    s.force[i].head<2>() -= phys.friction * normal / speed * slide;
  }
  for (size_t i = 0; i < n; ++i) {
    s.position[i] += dt * s.velocity[i];
    s.velocity[i] += dt * model.inv_mass[i] * s.force[i];
  }
}

}  // namespace hexgait
