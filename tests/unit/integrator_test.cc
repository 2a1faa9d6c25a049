#include "sim/integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "sim/state.h"
#include "test_util.h"
#include "tolerances.h"

namespace hexgait {
namespace {

TEST(Euler, StepMatchesHandComputation) {
  // Two particles 1.5 apart joined by a spring of rest length 1 (so stretched by 0.5), k = 10,
  // no damping, gravity 0.2, both well above the ground.
  CreatureModel m = test::TinyModel({{0, 0, 1}, {1.5, 0, 1}}, {2.0, 1.0}, {{0, 1}}, 10, 0, 0.2);
  m.rest_length[0] = 1.0;
  SimState s = MakeRestState(m);
  s.vx[0] = 0.3;
  s.vz[1] = -0.4;
  const double dt = 0.01;
  EulerStepper::Step(m, s, dt);
  // Spring force on particle 0: +k * 0.5 along +x = 5; on particle 1: -5.
  // Positions move with the OLD velocities; velocities with the OLD forces.
  EXPECT_DOUBLE_EQ(s.x[0], 0.0 + dt * 0.3);
  EXPECT_DOUBLE_EQ(s.z[1], 1.0 + dt * -0.4);
  EXPECT_DOUBLE_EQ(s.vx[0], 0.3 + dt * 5.0 / 2.0);
  EXPECT_DOUBLE_EQ(s.vz[0], 0.0 + dt * -0.2);
  EXPECT_DOUBLE_EQ(s.vx[1], 0.0 + dt * -5.0 / 1.0);
  EXPECT_DOUBLE_EQ(s.vz[1], -0.4 + dt * -0.2);
  EXPECT_EQ(s.step, 1);
}

TEST(Euler, ConservesMomentumWithoutGravityOrGround) {
  CreatureModel model = test::DefaultCreature();
  model.physics.gravity = 0;
  SimState s = MakeRestState(model);
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (int i = 0; i < s.num_particles(); ++i) {
    s.z[i] += 10.0;  // far above the ground
    s.vx[i] = 0.2 * std::sin(1.7 * i);
    s.vy[i] = 0.2 * std::cos(2.3 * i);
    s.vz[i] = 0.1 * std::sin(0.9 * i + 1);
    momentum += model.mass[i] * s.velocity(i);
  }
  // Disturb the springs so internal forces are large.
  for (int k = 0; k < model.num_springs(); ++k) s.rest_length[k] *= 1.0 + 0.05 * std::sin(k);
  for (int step = 0; step < 4000; ++step) EulerStepper::Step(model, s, 0.0025);
  Eigen::Vector3d after = Eigen::Vector3d::Zero();
  for (int i = 0; i < s.num_particles(); ++i) after += model.mass[i] * s.velocity(i);
  EXPECT_NEAR((after - momentum).norm(), 0.0, test::ConservationTol());
  // Internal forces really acted (the test would pass trivially otherwise).
  EXPECT_GT(std::fabs(s.vx[0] - 0.0), 1e-3);
}

// Leaves `model` standing from its rest pose for 100 time units under gravity alone, and checks
// it is still up and level; returns its body centre before and after.
std::pair<Eigen::Vector3d, Eigen::Vector3d> StandFor100TimeUnits(const CreatureModel& model,
                                                                 SimState& s) {
  const Eigen::Vector3d start = BodyCentre(model, s);
  for (int step = 0; step < 40000; ++step) EulerStepper::Step(model, s, 0.0025);
  EXPECT_GT(LowestBodyHeight(model, s), model.physics.fall_height + 0.1);
  EXPECT_LT(BodyTiltDegrees(model, s), 2.0);
  return {start, BodyCentre(model, s)};
}

// The wedge's feet stand under its body: at rest it settles completely.
TEST(Euler, RestingCreatureStaysStanding) {
  const CreatureModel model = LoadCreatureOrDefault("wedge");
  SimState s = MakeRestState(model);
  const auto [start, end] = StandFor100TimeUnits(model, s);
  EXPECT_NEAR(end.x(), start.x(), 1e-3);
  EXPECT_NEAR(end.y(), start.y(), 1e-3);
  // It sags a little under its own weight and settles (no bouncing left).
  EXPECT_LT(end.z(), start.z());
  EXPECT_LT(KineticEnergy(model, s), 1e-8);
}

// The hexapod's splayed legs load its feet sideways; below the slip velocity the regularised
// friction is viscous, so the loaded feet creep and the body drifts and sinks slowly instead
// of coming to rest (measured over 100 time units: 0.021 along x, kinetic energy 5.2e-7). It
// stays standing, level, and on its mirror plane.
TEST(Euler, RestingHexapodStaysStandingAndCreepsSlowly) {
  const CreatureModel model = test::DefaultCreature();
  SimState s = MakeRestState(model);
  const auto [start, end] = StandFor100TimeUnits(model, s);
  EXPECT_NEAR(end.x(), start.x(), 0.03);
  EXPECT_NEAR(end.y(), start.y(), 1e-3);
  EXPECT_LT(end.z(), start.z());
  EXPECT_LT(KineticEnergy(model, s), 1e-6);
}

}  // namespace
}  // namespace hexgait
