#include "model/rigidity.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace hexgait {

int RigidityRank(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::pair<int, int>>& edges) {
  const int n = static_cast<int>(points.size());
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(edges.size()), 3 * n);
  for (size_t e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    const Eigen::Vector3d d = points[a] - points[b];
    r.block<1, 3>(static_cast<Eigen::Index>(e), 3 * a) = d.transpose();
    r.block<1, 3>(static_cast<Eigen::Index>(e), 3 * b) = -d.transpose();
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(r);
  lu.setThreshold(1e-9);
  return static_cast<int>(lu.rank());
}

std::pair<int, int> BodyTrussRank(const CreatureModel& model) {
  std::vector<int> local(model.num_particles(), -1);
  std::vector<Eigen::Vector3d> points;
  for (int i : model.body_particles) {
    local[i] = static_cast<int>(points.size());
    points.push_back(model.rest_position[i]);
  }
  std::vector<std::pair<int, int>> edges;
  for (int s = 0; s < model.num_springs(); ++s) {
    const int a = local[model.spring_a[s]], b = local[model.spring_b[s]];
    if (a >= 0 && b >= 0) edges.emplace_back(a, b);
  }
  const int n = static_cast<int>(points.size());
  return {RigidityRank(points, edges), 3 * n - 6};
}

std::vector<double> PinnedFeetFrequencies(const CreatureModel& model) {
  std::vector<int> local(model.num_particles(), -1);
  const int n = static_cast<int>(model.body_particles.size());
  for (int k = 0; k < n; ++k) local[model.body_particles[k]] = k;
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int s = 0; s < model.num_springs(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Eigen::Vector3d u = (model.rest_position[b] - model.rest_position[a]).normalized();
    const Eigen::Matrix3d block = model.stiffness[s] * u * u.transpose();
    const int la = local[a], lb = local[b];
    if (la >= 0) stiffness.block<3, 3>(3 * la, 3 * la) += block;
    if (lb >= 0) stiffness.block<3, 3>(3 * lb, 3 * lb) += block;
    if (la >= 0 && lb >= 0) {
      stiffness.block<3, 3>(3 * la, 3 * lb) -= block;
      stiffness.block<3, 3>(3 * lb, 3 * la) -= block;
    }
  }
  Eigen::VectorXd inv_sqrt_mass(3 * n);
  for (int k = 0; k < n; ++k) {
    inv_sqrt_mass.segment<3>(3 * k).setConstant(1.0 /
                                                std::sqrt(model.mass[model.body_particles[k]]));
  }
  const Eigen::MatrixXd scaled =
      inv_sqrt_mass.asDiagonal() * stiffness * inv_sqrt_mass.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  std::vector<double> w;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i) {
    w.push_back(std::sqrt(std::max(0.0, eig.eigenvalues()[i])));
  }
  std::sort(w.begin(), w.end());
  return w;
}

bool EulerStableOscillator(double w2, double c, double dt) {
  // Step map [[1, dt], [-w2 dt, 1 - c dt]]: characteristic z^2 - tr z + det.
  const double tr = 2.0 - c * dt;
  const double det = 1.0 - c * dt + w2 * dt * dt;
  // Jury conditions for both roots inside the unit circle.
  return std::fabs(det) < 1.0 && 1.0 - tr + det > 0.0 && 1.0 + tr + det > 0.0;
}

double EulerLargestStableStep(double w2, double c) {
  double lo = 0, hi = 1.0;
  while (EulerStableOscillator(w2, c, hi) && hi < 1e6) hi *= 2;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (EulerStableOscillator(w2, c, mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace hexgait

namespace hexgait {
namespace {

Eigen::MatrixXd LinearisedSystem(const CreatureModel& model) {
  const int n = model.num_particles();
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Eigen::MatrixXd damping = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  auto add_pair = [&](Eigen::MatrixXd& m, int a, int b, const Eigen::Matrix3d& block) {
    m.block<3, 3>(3 * a, 3 * a) += block;
    m.block<3, 3>(3 * b, 3 * b) += block;
    m.block<3, 3>(3 * a, 3 * b) -= block;
    m.block<3, 3>(3 * b, 3 * a) -= block;
  };
  for (int s = 0; s < model.num_springs(); ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    const Eigen::Vector3d u = (model.rest_position[b] - model.rest_position[a]).normalized();
    const Eigen::Matrix3d uu = u * u.transpose();
    add_pair(stiffness, a, b, model.stiffness[s] * uu);
    add_pair(damping, a, b, model.damping[s] * uu);
  }
  int touching = 0;
  double total_mass = 0;
  for (int i = 0; i < n; ++i) {
    total_mass += model.mass[i];
    touching += model.rest_position[i].z() <= 1e-9;
  }
  const PhysicsConstants& phys = model.physics;
  const double normal = touching > 0 ? total_mass * phys.gravity / touching : 0.0;
  for (int i = 0; i < n; ++i) {
    if (model.rest_position[i].z() > 1e-9) continue;
    stiffness(3 * i + 2, 3 * i + 2) += phys.ground_stiffness;
    damping(3 * i + 2, 3 * i + 2) += phys.ground_damping;
    const double drag = phys.friction * normal / phys.slip_velocity;
    damping(3 * i, 3 * i) += drag;
    damping(3 * i + 1, 3 * i + 1) += drag;
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  a.topRightCorner(3 * n, 3 * n).setIdentity();
  for (int i = 0; i < 3 * n; ++i) {
    const double inv_mass = model.inv_mass[i / 3];
    a.block(3 * n + i, 0, 1, 3 * n) = -inv_mass * stiffness.row(i);
    a.block(3 * n + i, 3 * n, 1, 3 * n) = -inv_mass * damping.row(i);
  }
  return a;
}

}  // namespace

double LinearisedEulerSpectralRadius(const CreatureModel& model, double dt) {
  const Eigen::MatrixXd a = LinearisedSystem(model);
  const Eigen::MatrixXd step = Eigen::MatrixXd::Identity(a.rows(), a.cols()) + dt * a;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(step, /*computeEigenvectors=*/false);
  return solver.eigenvalues().cwiseAbs().maxCoeff();
}

double LinearisedEulerLargestStableStep(const CreatureModel& model) {
  // Free rigid motions (translation along the ground, yaw) give eigenvalues of exactly 1 for
  // any dt; a mode counts as unstable only above 1 + 1e-9.
  double lo = 0, hi = 0.5;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (LinearisedEulerSpectralRadius(model, mid) <= 1.0 + 1e-9 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace hexgait

namespace hexgait {

double LegConditioning(const CreatureModel& model, int leg) {
  const Leg& l = model.legs[leg];
  Eigen::MatrixXd directions(static_cast<Eigen::Index>(l.springs.size()), 3);
  for (size_t k = 0; k < l.springs.size(); ++k) {
    const int s = l.springs[k];
    const int anchor = model.spring_a[s] == l.foot ? model.spring_b[s] : model.spring_a[s];
    directions.row(static_cast<Eigen::Index>(k)) =
        (model.rest_position[l.foot] - model.rest_position[anchor]).normalized().transpose();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(directions);
  return svd.singularValues().minCoeff();
}

}  // namespace hexgait
