#include "adapt/gaussian_process.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/error.h"

namespace hexgait {

void ValidateGaussianProcessParams(const GaussianProcessParams& p) {
  if (!std::isfinite(p.length_scale) || p.length_scale <= 0) {
    throw InputError("the Gaussian process's length scale must be a positive number");
  }
  if (!std::isfinite(p.signal_variance) || p.signal_variance <= 0) {
    throw InputError("the Gaussian process's signal variance must be a positive number");
  }
  if (!std::isfinite(p.noise) || p.noise < 0) {
    throw InputError("the Gaussian process's noise variance must be a number >= 0");
  }
}

double Matern52(double r, const GaussianProcessParams& p) {
  const double s = std::sqrt(5.0) * r / p.length_scale;
  return p.signal_variance * (1.0 + s + s * s / 3.0) * std::exp(-s);
}

GaussianProcess::GaussianProcess(const GaussianProcessParams& params) : params_(params) {
  ValidateGaussianProcessParams(params_);
}

void GaussianProcess::Fit(const Eigen::MatrixXd& points, const Eigen::VectorXd& values,
                          const Eigen::VectorXd& prior_mean) {
  const Eigen::Index n = points.rows();
  if (values.size() != n || prior_mean.size() != n) {
    throw InputError("the Gaussian process needs one value and one prior mean per point (" +
                     std::to_string(n) + " points, " + std::to_string(values.size()) + " values, " +
                     std::to_string(prior_mean.size()) + " prior means)");
  }
  if (!points.allFinite() || !values.allFinite() || !prior_mean.allFinite()) {
    throw InputError("the Gaussian process's points, values and prior means must be finite");
  }
  Eigen::MatrixXd k(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) {
      k(i, j) = k(j, i) = Matern52((points.row(i) - points.row(j)).norm(), params_);
    }
    k(i, i) += params_.noise;
  }
  Eigen::LLT<Eigen::MatrixXd> llt(k);
  if (n > 0 && llt.info() != Eigen::Success) {
    throw InputError(
        "the Gaussian process's covariance matrix is not positive definite (the same point "
        "twice with no noise?); give it a positive noise variance");
  }
  points_ = points;
  llt_ = std::move(llt);
  // Algorithm 2.1, line 3: alpha = L^T \ (L \ (y - m)).
  alpha_ = n > 0 ? Eigen::VectorXd(llt_.solve(values - prior_mean)) : Eigen::VectorXd();
}

GaussianPrediction GaussianProcess::Predict(const Eigen::Ref<const Eigen::VectorXd>& point,
                                            double prior_mean) const {
  GaussianPrediction out{prior_mean, params_.signal_variance};
  const Eigen::Index n = points_.rows();
  if (n == 0) return out;
  if (point.size() != points_.cols()) {
    throw InputError("a point of " + std::to_string(point.size()) +
                     " values given to a Gaussian process fitted on " +
                     std::to_string(points_.cols()));
  }
  Eigen::VectorXd k_star(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    k_star[i] = Matern52((points_.row(i).transpose() - point).norm(), params_);
  }
  // Eq. 2.25 (plus the prior mean, eq. 2.38) and eq. 2.26 by Algorithm 2.1, lines 4-6.
  out.mean = prior_mean + k_star.dot(alpha_);
  const Eigen::VectorXd v = llt_.matrixL().solve(k_star);
  // Rounding can take k(x,x) - v.v a hair below zero at a training point with tiny noise.
  out.variance = std::max(0.0, params_.signal_variance - v.squaredNorm());
  return out;
}

}  // namespace hexgait
