#include "search/cma_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "ga/checkpoint_json.h"

namespace hexgait {
namespace {

using nlohmann::json;
using Vector = CmaDistribution::Vector;
using Matrix = CmaDistribution::Matrix;

constexpr int kMaxResamples = 100;

}  // namespace

json VectorJson(const Vector& v) {
  json out = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(Number(v[i]));
  return out;
}

Vector ReadVector(const JsonReader& r, const std::string& key, Eigen::Index size) {
  const JsonReader a = r.Child(key);
  if (static_cast<Eigen::Index>(a.ArraySize()) != size) {
    a.Fail("must have " + std::to_string(size) + " numbers");
  }
  Vector v(size);
  for (Eigen::Index i = 0; i < size; ++i) v[i] = a.At(static_cast<size_t>(i)).AsNumber();
  return v;
}

int DefaultCmaLambda(int n) {
  return 4 + static_cast<int>(std::floor(3 * std::log(n)));
}

CmaDistribution::CmaDistribution(int lambda, const Vector& mean, double sigma)
    : lambda_(lambda), mean_(mean), sigma_(sigma) {
  if (lambda_ < 2) throw std::logic_error("CMA-ES needs at least 2 samples per generation");
  const Eigen::Index n = mean_.size();
  SetStrategyParameters();
  c_ = Matrix::Identity(n, n);
  pc_ = ps_ = Vector::Zero(n);
  Decompose();
}

// Adaptation constants of the tutorial's Table 1 for n and lambda.
void CmaDistribution::SetStrategyParameters() {
  mu_ = lambda_ / 2;
  weights_.resize(mu_);
  for (int i = 0; i < mu_; ++i) weights_[i] = std::log((lambda_ + 1) / 2.0) - std::log(i + 1.0);
  weights_ /= weights_.sum();
  mueff_ = 1.0 / weights_.squaredNorm();
  const double n = static_cast<double>(mean_.size());
  cc_ = (4 + mueff_ / n) / (n + 4 + 2 * mueff_ / n);
  cs_ = (mueff_ + 2) / (n + mueff_ + 5);
  c1_ = 2 / ((n + 1.3) * (n + 1.3) + mueff_);
  cmu_ = std::min(1 - c1_, 2 * (mueff_ - 2 + 1 / mueff_) / ((n + 2) * (n + 2) + mueff_));
  damps_ = 1 + 2 * std::max(0.0, std::sqrt((mueff_ - 1) / (n + 1)) - 1) + cs_;
  chi_n_ = std::sqrt(n) * (1 - 1 / (4 * n) + 1 / (21 * n * n));
}

// Eigen's solver is deterministic for the same matrix and build.
bool CmaDistribution::Decompose() {
  // Symmetric to the last bit, so a matrix read back from a checkpoint decomposes the same.
  // (A loop: `c_ = (c_ + c_.transpose()) / 2` would read entries it has already written.)
  const Eigen::Index n = c_.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) c_(i, j) = c_(j, i) = (c_(i, j) + c_(j, i)) / 2;
  }
  const Eigen::SelfAdjointEigenSolver<Matrix> solver(c_);
  if (solver.info() != Eigen::Success) return false;
  b_ = solver.eigenvectors();
  const Vector values = solver.eigenvalues();
  d_ = values.cwiseMax(1e-300).cwiseSqrt();
  return values.allFinite() && values.minCoeff() > 0;
}

double CmaDistribution::LargestDeviation() const {
  return sigma_ * std::sqrt(c_.diagonal().maxCoeff());
}

Vector CmaDistribution::Sample(Rng& rng, double lower, double upper) const {
  const Eigen::Index n = mean_.size();
  Vector z(n), x(n);
  bool inside = false;
  for (int attempt = 0; attempt < kMaxResamples && !inside; ++attempt) {
    for (Eigen::Index i = 0; i < n; ++i) z[i] = rng.Normal();
    x = mean_ + sigma_ * (b_ * d_.cwiseProduct(z));
    inside = ((x.array() >= lower) && (x.array() <= upper)).all();
  }
  if (!inside) x = x.cwiseMax(lower).cwiseMin(upper);
  return x;
}

bool CmaDistribution::Update(const std::vector<const double*>& best_first, int generation) {
  if (static_cast<int>(best_first.size()) < mu_) {
    throw std::logic_error("CMA-ES update: fewer ranked samples than mu");
  }
  const Eigen::Index n = mean_.size();
  const auto x_of = [&](int i) {
    return Eigen::Map<const Vector>(best_first[static_cast<size_t>(i)], n);
  };
  const Vector old_mean = mean_;
  mean_.setZero();
  for (int i = 0; i < mu_; ++i) mean_ += weights_[i] * x_of(i);
  const Vector y_w = (mean_ - old_mean) / sigma_;
  // C^(-1/2) y_w = B D^-1 B^T y_w.
  const Vector c_inv_sqrt_y = b_ * (b_.transpose() * y_w).cwiseQuotient(d_);
  ps_ = (1 - cs_) * ps_ + std::sqrt(cs_ * (2 - cs_) * mueff_) * c_inv_sqrt_y;
  const double ps_norm = ps_.norm();
  const bool hsig = ps_norm / std::sqrt(1 - std::pow(1 - cs_, 2.0 * (generation + 1))) <
                    (1.4 + 2.0 / (static_cast<double>(n) + 1)) * chi_n_;
  pc_ = (1 - cc_) * pc_ + (hsig ? std::sqrt(cc_ * (2 - cc_) * mueff_) : 0.0) * y_w;
  Matrix rank_mu = Matrix::Zero(n, n);
  for (int i = 0; i < mu_; ++i) {
    const Vector y = (x_of(i) - old_mean) / sigma_;
    rank_mu.noalias() += weights_[i] * y * y.transpose();
  }
  const double delta_h = hsig ? 0.0 : cc_ * (2 - cc_);
  c_ = (1 - c1_ - cmu_ + c1_ * delta_h) * c_ + c1_ * pc_ * pc_.transpose() + cmu_ * rank_mu;
  sigma_ *= std::exp((cs_ / damps_) * (ps_norm / chi_n_ - 1));
  if (!std::isfinite(sigma_) || !(sigma_ > 0)) return false;
  Decompose();
  return true;
}

void CmaDistribution::Save(json& j) const {
  j["step_size"] = Number(sigma_);
  j["mean"] = VectorJson(mean_);
  j["path_c"] = VectorJson(pc_);
  j["path_sigma"] = VectorJson(ps_);
  j["covariance"] = VectorJson(Eigen::Map<const Vector>(c_.data(), c_.size()));
}

void CmaDistribution::Load(const JsonReader& r) {
  const Eigen::Index n = mean_.size();
  sigma_ = ReadNumber(r, "step_size");
  if (!std::isfinite(sigma_) || !(sigma_ > 0)) r.Fail("'step_size' must be positive");
  mean_ = ReadVector(r, "mean", n);
  pc_ = ReadVector(r, "path_c", n);
  ps_ = ReadVector(r, "path_sigma", n);
  if (!mean_.allFinite() || !pc_.allFinite() || !ps_.allFinite()) {
    r.Fail("'mean', 'path_c' and 'path_sigma' must be finite");
  }
  const Vector c = ReadVector(r, "covariance", n * n);
  c_ = Eigen::Map<const Matrix>(c.data(), n, n);
  // What Save writes is symmetric to the last bit (Decompose makes it so).
  if (!c_.allFinite() || c_ != c_.transpose()) r.Fail("'covariance' must be a symmetric matrix");
  if (!Decompose()) r.Fail("'covariance' must be positive definite");
}

}  // namespace hexgait
