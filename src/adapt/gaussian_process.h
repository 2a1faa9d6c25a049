// Gaussian-process regression over behaviour descriptors, for Intelligent Trial and Error
// (Cully, Clune, Tarapore and Mouret, "Robots that adapt like animals", Nature 521, 503-507,
// 2015): the prior mean at an elite is the distance the repertoire recorded for it, and each
// trial on the damaged creature updates the posterior around its descriptor.
//
// Written after Rasmussen and Williams, "Gaussian Processes for Machine Learning" (MIT Press,
// 2006): the predictive mean and variance of eq. 2.25-2.26 (with a prior mean function, as in
// sec. 2.7, eq. 2.38: the GP models the residual y - m(x)), computed by the Cholesky route of
// Algorithm 2.1, and the Matern class's nu = 5/2 member (sec. 4.2, eq. 4.17).
//
// Hyperparameters are fixed, not fitted: a handful of trials cannot estimate them, and the ITE
// code (resibots/ITE, hexa_bomean.cpp, on limbo) fixes them too: length scale 0.4, signal
// variance 1 (limbo's kf_maternfivehalfs sigma), noise 0.001 (boptimizer noise).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace hexgait {

struct GaussianProcessParams {
  double length_scale = 0.4;     // l, in descriptor units (descriptors lie in [0, 1]^d)
  double signal_variance = 1.0;  // sigma^2: the prior variance of f - m at any point
  double noise = 0.001;          // observation noise variance, added to the kernel's diagonal
};

// Throws InputError unless the length scale and signal variance are positive and finite and the
// noise is finite and not negative.
void ValidateGaussianProcessParams(const GaussianProcessParams& params);

// The Matern 5/2 covariance at distance r: sigma^2 (1 + sqrt5 r/l + 5 r^2/(3 l^2))
// exp(-sqrt5 r/l). Rasmussen and Williams eq. 4.17 times the signal variance.
double Matern52(double r, const GaussianProcessParams& params);

struct GaussianPrediction {
  double mean = 0;
  double variance = 0;  // of the latent function, without the observation noise
};

class GaussianProcess {
 public:
  explicit GaussianProcess(const GaussianProcessParams& params);  // validates them

  // Conditions on n observations: points (n x d, one row each), their observed values and the
  // prior mean at each. Replaces any earlier fit. Throws InputError for mismatched sizes, a
  // non-finite value, or a covariance matrix that is not positive definite (the same point twice
  // with zero noise), rather than returning NaN later.
  void Fit(const Eigen::MatrixXd& points, const Eigen::VectorXd& values,
           const Eigen::VectorXd& prior_mean);

  // The posterior at `point` (d values, or any d if nothing is fitted), whose prior mean is
  // `prior_mean`. With no observations: the prior mean and the signal variance.
  GaussianPrediction Predict(const Eigen::Ref<const Eigen::VectorXd>& point,
                             double prior_mean) const;

  int num_observations() const { return static_cast<int>(points_.rows()); }
  const GaussianProcessParams& params() const { return params_; }

 private:
  GaussianProcessParams params_;
  Eigen::MatrixXd points_;
  Eigen::LLT<Eigen::MatrixXd> llt_;  // of K + noise I
  Eigen::VectorXd alpha_;            // (K + noise I)^-1 (y - m)
};

}  // namespace hexgait
