// Linearised backward Euler (Baraff & Witkin, "Large steps in cloth simulation", 1998): one
// Newton step of v_{k+1} = v_k + dt M^-1 f(x_{k+1}, v_{k+1}), x_{k+1} = x_k + dt v_{k+1}, with
// the force linearised at the current state:
//   (M - dt D - dt^2 K) dv = dt (f + dt K v),   v += dv,   x += dt v,
// K = df/dx and D = df/dv the full 3N x 3N Jacobians of springs (with damping) and ground contact
// with friction (sim/jacobian.h). Friction and contact make them unsymmetric, so the system is
// solved by LU with partial pivoting. First order, but stable far beyond explicit methods' step.
// All matrices are sized in the constructor; Step never allocates (tests/unit/no_alloc_test.cc).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/creature.h"
#include "sim/state.h"

namespace hexgait {

class ImplicitEulerStepper {
 public:
  explicit ImplicitEulerStepper(const CreatureModel& model);
  void Begin(const CreatureModel&, SimState&) {}
  void Step(const CreatureModel& model, SimState& state, double dt);

 private:
  Eigen::MatrixXd df_dx_, df_dv_, system_;
  Eigen::VectorXd velocity_, rhs_, dv_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace hexgait
