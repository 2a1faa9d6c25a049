#include "sim/forces.h"

#include <cmath>

#include "sim/scalar_ops.h"

namespace hexgait {
namespace {

GroundConstants<double> GroundOf(const PhysicsConstants& physics) {
  return {physics.ground_stiffness, physics.ground_damping, physics.friction,
          physics.slip_velocity * physics.slip_velocity};
}

}  // namespace

void ComputeForces(const CreatureModel& model, const double* rest_length, ParticleView p,
                   ForceView f) {
  // Restrict-qualified locals tell the compiler the force arrays never alias the positions, so
  // it keeps values in registers across the scattered force updates.
  const double* __restrict x = p.x;
  const double* __restrict y = p.y;
  const double* __restrict z = p.z;
  const double* __restrict vx = p.vx;
  const double* __restrict vy = p.vy;
  const double* __restrict vz = p.vz;
  double* __restrict fx = f.fx;
  double* __restrict fy = f.fy;
  double* __restrict fz = f.fz;
  const int n = model.num_particles();
  const double g = model.physics.gravity;
  const double gx = model.physics.gravity_x;
  const double* __restrict mass = model.mass.data();
  for (int i = 0; i < n; ++i) {
    fx[i] = mass[i] * gx;
    fy[i] = 0;
    fz[i] = -mass[i] * g;
  }

  // Springs (Physics::Spring). First every spring's force (independent iterations, so the square
  // roots and divisions of different springs overlap in the pipeline), then the scatter onto
  // particles.
  const int ns = model.num_springs();
  const int* __restrict sa = model.spring_a.data();
  const int* __restrict sb = model.spring_b.data();
  const double* __restrict k = model.stiffness.data();
  const double* __restrict c = model.damping.data();
  const double* __restrict rest = rest_length;
  double* __restrict sfx = f.spring_fx;
  double* __restrict sfy = f.spring_fy;
  double* __restrict sfz = f.spring_fz;
  for (int s = 0; s < ns; ++s) {
    const int a = sa[s], b = sb[s];
    ScalarPhysics::Spring(x[b] - x[a], y[b] - y[a], z[b] - z[a], vx[b] - vx[a], vy[b] - vy[a],
                          vz[b] - vz[a], k[s], c[s], rest[s], sfx[s], sfy[s], sfz[s]);
  }
  for (int s = 0; s < ns; ++s) {
    const int a = sa[s], b = sb[s];
    fx[a] += sfx[s];
    fy[a] += sfy[s];
    fz[a] += sfz[s];
    fx[b] -= sfx[s];
    fy[b] -= sfy[s];
    fz[b] -= sfz[s];
  }

  // Ground contact, particle by particle (most skip it: they are above the ground).
  const GroundConstants<double> ground = GroundOf(model.physics);
  for (int i = 0; i < n; ++i)
    ScalarPhysics::Ground(ground, z[i], vx[i], vy[i], vz[i], fx[i], fy[i], fz[i]);
}

}  // namespace hexgait

namespace hexgait {

Eigen::Vector3d SpringForceOnB(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& va, const Eigen::Vector3d& vb,
                               double stiffness, double damping, double rest_length) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const Eigen::Vector3d u = d / length;
  return -(stiffness * (length - rest_length) + damping * (vb - va).dot(u)) * u;
}

Eigen::Matrix3d SpringStiffnessBlock(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     double stiffness, double rest_length) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const Eigen::Vector3d u = d / length;
  const Eigen::Matrix3d uu = u * u.transpose();
  // f_b = -k (L - L0) u: differentiating L gives u u^T, differentiating u gives
  // (I - u u^T) / L.
  return -stiffness * (uu + (1.0 - rest_length / length) * (Eigen::Matrix3d::Identity() - uu));
}

void SpringJacobianBlocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& va, const Eigen::Vector3d& vb, double stiffness,
                          double damping, double rest_length, Eigen::Matrix3d* df_dx,
                          Eigen::Matrix3d* df_dv) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const Eigen::Vector3d u = d / length;
  const Eigen::Matrix3d uu = u * u.transpose();
  const Eigen::Matrix3d p = Eigen::Matrix3d::Identity() - uu;  // d u / d x_b = p / L
  const Eigen::Vector3d w = vb - va;
  const double rate = w.dot(u);
  const double magnitude = stiffness * (length - rest_length) + damping * rate;
  // f_b = -m u with m = k (L - L0) + c (w . u): d m / d x_b = k u^T + c w^T p / L.
  *df_dx =
      -(stiffness * uu + (magnitude / length) * p + (damping / length) * u * (w.transpose() * p));
  *df_dv = -damping * uu;
}

}  // namespace hexgait
