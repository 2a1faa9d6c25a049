// The implicit integrator's Jacobians against central finite differences of the forces.
#include "sim/jacobian.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/state.h"
#include "test_util.h"
#include "tolerances.h"

namespace hexgait {
namespace {

TEST(Jacobian, SpringBlocksMatchFiniteDifferences) {
  const Eigen::Vector3d a(0.1, -0.2, 0.3), b(1.2, 0.4, 0.1);
  const Eigen::Vector3d va(0.3, -0.1, 0.2), vb(-0.4, 0.5, 0.1);
  const double k = 50, c = 3, rest = 1.1, h = 1e-6;
  Eigen::Matrix3d jx, jv;
  SpringJacobianBlocks(a, b, va, vb, k, c, rest, &jx, &jv);
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(j) * h;
    const Eigen::Vector3d dx = (SpringForceOnB(a, b + e, va, vb, k, c, rest) -
                                SpringForceOnB(a, b - e, va, vb, k, c, rest)) /
                               (2 * h);
    const Eigen::Vector3d dv = (SpringForceOnB(a, b, va, vb + e, k, c, rest) -
                                SpringForceOnB(a, b, va, vb - e, k, c, rest)) /
                               (2 * h);
    EXPECT_LT((jx.col(j) - dx).norm(), test::FiniteDifferenceTol() * jx.norm());
    EXPECT_LT((jv.col(j) - dv).norm(), test::FiniteDifferenceTol() * jv.norm());
  }
  // Without damping the position block is the pure stiffness block.
  SpringJacobianBlocks(a, b, va, vb, k, 0, rest, &jx, &jv);
  EXPECT_LT((jx - SpringStiffnessBlock(a, b, k, rest)).norm(), 1e-12 * jx.norm());
}

// Total force on every particle, as one 3N vector.
Eigen::VectorXd Forces(const CreatureModel& m, SimState s) {
  ComputeForces(m, s.rest_length.data(), s.particle_view(), s.force_view());
  Eigen::VectorXd f(3 * s.num_particles());
  for (int i = 0; i < s.num_particles(); ++i) f.segment<3>(3 * i) << s.fx[i], s.fy[i], s.fz[i];
  return f;
}

TEST(Jacobian, WholeCreatureWithContactAndFriction) {
  const CreatureModel m = test::DefaultCreature();
  SimState s = MakeRestState(m);
  // Sink the creature into the ground and set it sliding, so contact and friction (including
  // the viscous zone below slip_velocity) all contribute.
  for (int i = 0; i < s.num_particles(); ++i) {
    s.x[i] += 0.01 * std::sin(1.3 * i);
    s.z[i] -= 0.004 + 0.002 * std::cos(0.7 * i);
    s.vx[i] = 0.03 * std::sin(2.1 * i);
    s.vy[i] = 0.01 * std::cos(1.1 * i);
    s.vz[i] = -0.002 * std::sin(0.5 * i);
  }
  for (int k = 0; k < m.num_springs(); ++k) s.rest_length[k] *= 1.0 + 0.03 * std::sin(k);
  const int n3 = 3 * s.num_particles();
  Eigen::MatrixXd kx(n3, n3), dv(n3, n3);
  ForceJacobians(m, s.rest_length.data(), s.particle_view(), kx, dv);
  int in_contact = 0;
  for (int i = 0; i < s.num_particles(); ++i) in_contact += s.z[i] < 0;
  ASSERT_GT(in_contact, 3);

  const double h = 1e-7;
  std::vector<double>* pos[3] = {&s.x, &s.y, &s.z};
  std::vector<double>* vel[3] = {&s.vx, &s.vy, &s.vz};
  for (int col = 0; col < n3; ++col) {
    for (int which = 0; which < 2; ++which) {
      double& q = (*(which == 0 ? pos : vel)[col % 3])[col / 3];
      const double saved = q;
      q = saved + h;
      const Eigen::VectorXd plus = Forces(m, s);
      q = saved - h;
      const Eigen::VectorXd minus = Forces(m, s);
      q = saved;
      const Eigen::VectorXd fd = (plus - minus) / (2 * h);
      const Eigen::VectorXd analytic = which == 0 ? kx.col(col) : dv.col(col);
      EXPECT_LT((analytic - fd).norm(), 1e-5 * (1.0 + analytic.norm()))
          << (which == 0 ? "d f / d x" : "d f / d v") << " column " << col;
    }
  }
}

}  // namespace
}  // namespace hexgait
