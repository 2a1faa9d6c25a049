#include "sim/forces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/integrator.h"
#include "sim/state.h"
#include "test_util.h"
#include "tolerances.h"

namespace hexgait {
namespace {

double SpringEnergy(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double k, double rest) {
  const double stretch = (b - a).norm() - rest;
  return 0.5 * k * stretch * stretch;
}

TEST(SpringForce, IsMinusTheEnergyGradient) {
  const Eigen::Vector3d a(0.1, -0.3, 0.7), b(1.2, 0.4, 0.2);
  const double k = 37.0, rest = 0.9, h = 1e-6;
  const Eigen::Vector3d force =
      SpringForceOnB(a, b, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), k, 0.0, rest);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d plus = b, minus = b;
    plus[axis] += h;
    minus[axis] -= h;
    const double gradient =
        (SpringEnergy(a, plus, k, rest) - SpringEnergy(a, minus, k, rest)) / (2 * h);
    EXPECT_NEAR(force[axis], -gradient, test::FiniteDifferenceTol()) << "axis " << axis;
  }
}

TEST(SpringForce, StiffnessBlockMatchesFiniteDifferences) {
  // Compressed and stretched springs: the geometric term changes sign.
  for (double rest : {0.5, 1.3, 2.5}) {
    const Eigen::Vector3d a(0.2, 0.1, -0.4), b(-0.6, 0.9, 0.5);
    const double k = 12.5, h = 1e-6;
    const Eigen::Matrix3d block = SpringStiffnessBlock(a, b, k, rest);
    for (int axis = 0; axis < 3; ++axis) {
      Eigen::Vector3d plus = b, minus = b;
      plus[axis] += h;
      minus[axis] -= h;
      const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
      const Eigen::Vector3d column = (SpringForceOnB(a, plus, zero, zero, k, 0, rest) -
                                      SpringForceOnB(a, minus, zero, zero, k, 0, rest)) /
                                     (2 * h);
      for (int row = 0; row < 3; ++row) {
        EXPECT_NEAR(block(row, axis), column[row], test::FiniteDifferenceTol() * k)
            << "rest " << rest << " row " << row << " col " << axis;
      }
    }
  }
}

TEST(SpringForce, DampingOpposesStretchingRate) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0);
  const Eigen::Vector3d f =
      SpringForceOnB(a, b, Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 5, 0), 10.0, 3.0, 1.0);
  // At rest length, only damping acts: -c * (rate along the spring) = -3 * 2; the sideways
  // velocity does not change the length and gives no force.
  EXPECT_DOUBLE_EQ(f.x(), -6.0);
  EXPECT_DOUBLE_EQ(f.y(), 0.0);
}

TEST(ComputeForces, MatchesSumOfSpringsAndGravityAboveGround) {
  CreatureModel model = test::DefaultCreature();
  SimState s = MakeRestState(model);
  // Lift it off the ground and disturb it so every spring is stretched and moving.
  for (int i = 0; i < s.num_particles(); ++i) {
    s.z[i] += 5.0;
    s.x[i] += 0.05 * std::sin(3.0 * i);
    s.vy[i] = 0.1 * std::cos(5.0 * i);
  }
  ComputeForces(model, s.rest_length.data(), s.particle_view(), s.force_view());
  std::vector<Eigen::Vector3d> expected(model.num_particles(), Eigen::Vector3d::Zero());
  for (int i = 0; i < model.num_particles(); ++i) {
    expected[i].z() = -model.mass[i] * model.physics.gravity;
  }
  for (int k = 0; k < model.num_springs(); ++k) {
    const int a = model.spring_a[k], b = model.spring_b[k];
    const Eigen::Vector3d f =
        SpringForceOnB(s.position(a), s.position(b), s.velocity(a), s.velocity(b),
                       model.stiffness[k], model.damping[k], s.rest_length[k]);
    expected[b] += f;
    expected[a] -= f;
  }
  for (int i = 0; i < model.num_particles(); ++i) {
    EXPECT_NEAR(s.fx[i], expected[i].x(), 1e-12);
    EXPECT_NEAR(s.fy[i], expected[i].y(), 1e-12);
    EXPECT_NEAR(s.fz[i], expected[i].z(), 1e-12);
  }
}

TEST(GroundContact, PushesUpAndFrictionOpposesSliding) {
  CreatureModel m = test::TinyModel({{0, 0, -0.01}, {5, 0, 1}}, {1.0, 1.0}, {}, 1, 0, 0.0);
  m.physics.ground_stiffness = 400;
  m.physics.ground_damping = 0;
  m.physics.friction = 0.5;
  m.physics.slip_velocity = 1e-3;
  SimState s = MakeRestState(m);
  s.vx[0] = 1.0;  // sliding fast: full Coulomb friction
  ComputeForces(m, s.rest_length.data(), s.particle_view(), s.force_view());
  EXPECT_DOUBLE_EQ(s.fz[0], 4.0);  // 400 * 0.01
  EXPECT_NEAR(s.fx[0], -0.5 * 4.0, 1e-5);
  EXPECT_DOUBLE_EQ(s.fy[0], 0.0);
  // The particle above the ground feels nothing.
  EXPECT_EQ(s.fx[1], 0.0);
  EXPECT_EQ(s.fz[1], 0.0);
}

TEST(GroundContact, NeverPullsDown) {
  CreatureModel m = test::TinyModel({{0, 0, -0.001}}, {1.0}, {}, 1, 0, 0.0);
  m.physics.ground_stiffness = 100;
  m.physics.ground_damping = 50;
  SimState s = MakeRestState(m);
  s.vz[0] = 1.0;  // leaving the ground fast: damping would pull down; the contact must not
  ComputeForces(m, s.rest_length.data(), s.particle_view(), s.force_view());
  EXPECT_EQ(s.fz[0], 0.0);
}

TEST(Spring, AtRestDoesNotMove) {
  CreatureModel m = test::TinyModel({{0, 0, 3}, {1, 0.5, 3.2}}, {1.0, 2.0}, {{0, 1}}, 50, 1, 0.0);
  SimState s = MakeRestState(m);
  const SimState start = s;
  for (int i = 0; i < 1000; ++i) EulerStepper::Step(m, s, 0.0025);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(s.x[i], start.x[i]);
    EXPECT_EQ(s.y[i], start.y[i]);
    EXPECT_EQ(s.z[i], start.z[i]);
    EXPECT_EQ(s.vx[i], 0.0);
  }
}

}  // namespace
}  // namespace hexgait
