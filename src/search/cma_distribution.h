// The search distribution of CMA-ES, written once for every optimizer that adapts one: `evolve
// --algorithm cmaes` (search/cmaes_optimizer.cc) and the emitters of CMA-MAE. It follows
// N. Hansen, "The CMA Evolution Strategy: A Tutorial" (arXiv:1604.00772, 2016), Algorithm 1 with
// positive weights only, with the tutorial's default constants for n dimensions and lambda
// samples. Samples are bounded to a box as Debian's python3-cmaes bounds them: a sample outside
// is drawn again, and after 100 draws clipped.
//
// The normal numbers come from the caller's Rng (ga/rng.h, Box-Muller), so a saved distribution
// (mean, step size, covariance, evolution paths) continues with the same bits.
#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ga/rng.h"
#include "util/json_file.h"

namespace hexgait {

// A vector as a JSON array of exact numbers, and back (failing through `r` unless it has `size`).
nlohmann::json VectorJson(const Eigen::VectorXd& v);
Eigen::VectorXd ReadVector(const JsonReader& r, const std::string& key, Eigen::Index size);

// Hansen's default number of samples per generation for n dimensions: 4 + floor(3 ln n).
int DefaultCmaLambda(int n);

class CmaDistribution {
 public:
  using Vector = Eigen::VectorXd;
  using Matrix = Eigen::MatrixXd;

  // n dimensions, lambda samples per generation (at least 2), centred on `mean` with step
  // size `sigma` and the identity covariance.
  CmaDistribution(int lambda, const Vector& mean, double sigma);

  int dims() const { return static_cast<int>(mean_.size()); }
  int lambda() const { return lambda_; }
  int mu() const { return mu_; }
  double sigma() const { return sigma_; }
  const Vector& mean() const { return mean_; }
  // The largest standard deviation along an axis: sigma * sqrt(max diag C).
  double LargestDeviation() const;

  // One sample in [lower, upper]^n.
  Vector Sample(Rng& rng, double lower, double upper) const;

  // Moves the distribution towards this generation's best: `best_first` holds at least mu()
  // samples (each dims() numbers) in order of merit. `generation` counts updates from 1 (the
  // h_sigma test's correction). Returns false, changing nothing after the failed step, when the
  // step size stops being a positive number.
  bool Update(const std::vector<const double*>& best_first, int generation);

  // The state as members of `j`: "step_size", "mean", "path_c", "path_sigma", "covariance".
  void Save(nlohmann::json& j) const;
  // Reads what Save wrote; fails through `r` on a non-positive step size, wrong lengths or a
  // covariance that is not symmetric positive definite.
  void Load(const JsonReader& r);

 private:
  void SetStrategyParameters();
  // C = B D^2 B^T; false when C is not positive definite.
  bool Decompose();

  int lambda_ = 0, mu_ = 0;
  Vector weights_;
  double mueff_ = 0, cc_ = 0, cs_ = 0, c1_ = 0, cmu_ = 0, damps_ = 0, chi_n_ = 0;

  Vector mean_, pc_, ps_, d_;
  Matrix c_, b_;
  double sigma_ = 0;
};

}  // namespace hexgait
