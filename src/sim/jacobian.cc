#include "sim/jacobian.h"

#include <cmath>

namespace hexgait {

void ForceJacobians(const CreatureModel& model, const double* rest_length, ParticleView p,
                    Eigen::MatrixXd& df_dx, Eigen::MatrixXd& df_dv) {
  df_dx.setZero();
  df_dv.setZero();
  for (int s = 0; s < model.num_springs(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Eigen::Vector3d xa(p.x[a], p.y[a], p.z[a]), xb(p.x[b], p.y[b], p.z[b]);
    const Eigen::Vector3d va(p.vx[a], p.vy[a], p.vz[a]), vb(p.vx[b], p.vy[b], p.vz[b]);
    Eigen::Matrix3d jx, jv;
    SpringJacobianBlocks(xa, xb, va, vb, model.stiffness[s], model.damping[s], rest_length[s], &jx,
                         &jv);
    // f_b depends on x_b - x_a and f_a = -f_b: the four blocks are +-J.
    df_dx.block<3, 3>(3 * b, 3 * b) += jx;
    df_dx.block<3, 3>(3 * a, 3 * a) += jx;
    df_dx.block<3, 3>(3 * b, 3 * a) -= jx;
    df_dx.block<3, 3>(3 * a, 3 * b) -= jx;
    df_dv.block<3, 3>(3 * b, 3 * b) += jv;
    df_dv.block<3, 3>(3 * a, 3 * a) += jv;
    df_dv.block<3, 3>(3 * b, 3 * a) -= jv;
    df_dv.block<3, 3>(3 * a, 3 * b) -= jv;
  }

  // Ground, as in ComputeForces: N = -kg z - dg vz (when positive), f_z += N, and friction
  // f_t = -mu N v_t / s with s = sqrt(|v_t|^2 + eps^2).
  const PhysicsConstants& phys = model.physics;
  const double kg = phys.ground_stiffness, dg = phys.ground_damping, mu = phys.friction;
  const double eps2 = phys.slip_velocity * phys.slip_velocity;
  for (int i = 0; i < model.num_particles(); ++i) {
    if (p.z[i] >= 0) continue;
    const double normal = -kg * p.z[i] - dg * p.vz[i];
    if (normal <= 0) continue;
    const double vx = p.vx[i], vy = p.vy[i];
    const double speed = std::sqrt(vx * vx + vy * vy + eps2);
    const double inv_s = 1.0 / speed, inv_s3 = inv_s * inv_s * inv_s;
    const int r = 3 * i;
    df_dx(r + 2, r + 2) += -kg;
    df_dv(r + 2, r + 2) += -dg;
    // Through N: d f_x / d z = mu kg vx / s, d f_x / d vz = mu dg vx / s.
    df_dx(r + 0, r + 2) += mu * kg * vx * inv_s;
    df_dx(r + 1, r + 2) += mu * kg * vy * inv_s;
    df_dv(r + 0, r + 2) += mu * dg * vx * inv_s;
    df_dv(r + 1, r + 2) += mu * dg * vy * inv_s;
    // Through the direction of sliding.
    df_dv(r + 0, r + 0) += -mu * normal * (inv_s - vx * vx * inv_s3);
    df_dv(r + 1, r + 1) += -mu * normal * (inv_s - vy * vy * inv_s3);
    df_dv(r + 0, r + 1) += mu * normal * vx * vy * inv_s3;
    df_dv(r + 1, r + 0) += mu * normal * vx * vy * inv_s3;
  }
}

}  // namespace hexgait
