// The Gaussian process of Intelligent Trial and Error (adapt/gaussian_process.h): its kernel,
// the posterior's limits (at a noiseless observation, far from every observation) and a case
// worked by hand; tests/python/test_gaussian_process.py checks it against scikit-learn.
#include "adapt/gaussian_process.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace hexgait {
namespace {

TEST(GaussianProcess, Matern52IsTheSignalVarianceAtZeroAndFallsWithDistance) {
  GaussianProcessParams p;
  p.length_scale = 0.4;
  p.signal_variance = 2.5;
  EXPECT_DOUBLE_EQ(Matern52(0, p), 2.5);
  // At r = l: sigma^2 (1 + sqrt5 + 5/3) exp(-sqrt5).
  EXPECT_NEAR(Matern52(0.4, p), 2.5 * (1 + std::sqrt(5.0) + 5.0 / 3.0) * std::exp(-std::sqrt(5.0)),
              1e-15);
  EXPECT_GT(Matern52(0.1, p), Matern52(0.2, p));
  EXPECT_LT(Matern52(50, p), 1e-100);
}

TEST(GaussianProcess, WithoutDataItIsThePrior) {
  GaussianProcessParams p;
  p.signal_variance = 3;
  const GaussianProcess gp(p);
  const GaussianPrediction at = gp.Predict(Eigen::Vector2d(0.5, 0.5), 7.0);
  EXPECT_EQ(at.mean, 7.0);
  EXPECT_EQ(at.variance, 3.0);
}

TEST(GaussianProcess, AtAnObservationWithTinyNoiseItIsTheObservation) {
  GaussianProcessParams p;
  p.noise = 1e-10;
  GaussianProcess gp(p);
  Eigen::MatrixXd x(3, 2);
  x << 0.1, 0.2, 0.5, 0.5, 0.9, 0.3;
  const Eigen::Vector3d y(4.0, -1.0, 2.5), prior(3.0, 3.0, 1.0);
  gp.Fit(x, y, prior);
  for (int i = 0; i < 3; ++i) {
    const GaussianPrediction at = gp.Predict(x.row(i).transpose(), prior[i]);
    EXPECT_NEAR(at.mean, y[i], 1e-8) << i;
    EXPECT_NEAR(at.variance, 0.0, 1e-8) << i;
  }
}

TEST(GaussianProcess, FarFromTheDataItIsThePriorMeanAndVariance) {
  GaussianProcessParams p;
  p.signal_variance = 1.7;
  GaussianProcess gp(p);
  Eigen::MatrixXd x(2, 2);
  x << 0.1, 0.1, 0.2, 0.3;
  gp.Fit(x, Eigen::Vector2d(9.0, -9.0), Eigen::Vector2d(0.0, 0.0));
  const GaussianPrediction far = gp.Predict(Eigen::Vector2d(40.0, 40.0), 5.0);
  EXPECT_DOUBLE_EQ(far.mean, 5.0);
  EXPECT_DOUBLE_EQ(far.variance, 1.7);
}

// Two observations in one dimension, l = 0.4, sigma^2 = 1, noise 0.01: the 2x2 system inverted
// by hand, against the numbers NumPy gives for the same formulas (eq. 2.25-2.26).
TEST(GaussianProcess, TwoPointsByHand) {
  GaussianProcessParams p;
  p.noise = 0.01;
  GaussianProcess gp(p);
  Eigen::MatrixXd x(2, 1);
  x << 0.0, 0.3;
  const Eigen::Vector2d y(2.0, 1.0), prior(1.5, 1.5);
  gp.Fit(x, y, prior);
  const double k12 = Matern52(0.3, p), a = Matern52(0.1, p), b = Matern52(0.2, p);
  EXPECT_NEAR(k12, 0.6756478000186599, 1e-15);
  const double d = 1.0 + p.noise, det = d * d - k12 * k12;
  // (K + noise I)^-1 = [d, -k12; -k12, d] / det.
  const double r1 = y[0] - prior[0], r2 = y[1] - prior[1];
  const double mean = 1.2 + (a * (d * r1 - k12 * r2) + b * (-k12 * r1 + d * r2)) / det;
  const double var = 1.0 - (a * (d * a - k12 * b) + b * (-k12 * a + d * b)) / det;
  const GaussianPrediction at = gp.Predict(Eigen::VectorXd::Constant(1, 0.1), 1.2);
  EXPECT_NEAR(at.mean, mean, 1e-13);
  EXPECT_NEAR(at.variance, var, 1e-13);
  EXPECT_NEAR(at.mean, 1.3829070950741968, 1e-13);
  EXPECT_NEAR(at.variance, 0.03822453541227033, 1e-13);
}

TEST(GaussianProcess, RefusesASingularMatrixAndBadInput) {
  GaussianProcessParams p;
  p.noise = 0;
  GaussianProcess gp(p);
  Eigen::MatrixXd twice(2, 2);
  twice << 0.5, 0.5, 0.5, 0.5;
  try {
    gp.Fit(twice, Eigen::Vector2d(1, 2), Eigen::Vector2d(0, 0));
    FAIL() << "a singular covariance matrix was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos);
  }
  EXPECT_THROW(gp.Fit(twice, Eigen::Vector3d(1, 2, 3), Eigen::Vector2d(0, 0)), InputError);
  EXPECT_THROW(gp.Fit(twice, Eigen::Vector2d(1, NAN), Eigen::Vector2d(0, 0)), InputError);
  for (double bad : {0.0, -1.0, double{INFINITY}}) {
    GaussianProcessParams q;
    q.length_scale = bad;
    EXPECT_THROW(GaussianProcess{q}, InputError);
    q = GaussianProcessParams{};
    q.signal_variance = bad;
    EXPECT_THROW(GaussianProcess{q}, InputError);
  }
  GaussianProcessParams q;
  q.noise = -1e-3;
  EXPECT_THROW(GaussianProcess{q}, InputError);
  // A point of the wrong dimension once fitted.
  p.noise = 0.001;
  GaussianProcess fitted(p);
  fitted.Fit(twice, Eigen::Vector2d(1, 2), Eigen::Vector2d(0, 0));
  EXPECT_THROW(fitted.Predict(Eigen::Vector3d(0, 0, 0), 0), InputError);
}

}  // namespace
}  // namespace hexgait
