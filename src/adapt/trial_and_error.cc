#include "adapt/trial_and_error.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/error.h"

namespace hexgait {
namespace {

void CheckArchive(const std::vector<ArchiveElite>& archive) {
  if (archive.empty()) throw InputError("trial and error needs at least one elite");
  const Eigen::Index d = archive.front().descriptor.size();
  for (size_t i = 0; i < archive.size(); ++i) {
    const ArchiveElite& e = archive[i];
    if (e.descriptor.size() != d) {
      throw InputError("elite " + std::to_string(i) + " has a descriptor of " +
                       std::to_string(e.descriptor.size()) + " values, elite 0 of " +
                       std::to_string(d));
    }
    if (!e.descriptor.allFinite() || !std::isfinite(e.distance)) {
      throw InputError("elite " + std::to_string(i) + " has a non-finite descriptor or distance");
    }
  }
}

}  // namespace

void ValidateTrialAndErrorParams(const TrialAndErrorParams& p) {
  ValidateGaussianProcessParams(p.gp);
  if (!std::isfinite(p.kappa) || p.kappa < 0) {
    throw InputError("kappa (the UCB's weight on the standard deviation) must be a number >= 0");
  }
  if (!(p.stop_fraction > 0 && p.stop_fraction <= 1)) {
    throw InputError("the stop fraction must be in (0, 1]");
  }
  if (p.max_trials < 1) throw InputError("trial and error needs at least 1 trial");
}

TrialAndErrorParams IteCodeParams() {
  TrialAndErrorParams params;
  params.gp = GaussianProcessParams{};
  params.normalise = Normalisation::kNone;
  return params;
}

Normalisation ParseNormalisation(const std::string& name) {
  if (name == "none") return Normalisation::kNone;
  if (name == "best") return Normalisation::kBest;
  if (name == "spread") return Normalisation::kSpread;
  throw InputError("--normalise must be " + std::string(kNormalisationNames) + " (got '" + name +
                   "')");
}

std::string NormalisationName(Normalisation normalisation) {
  switch (normalisation) {
    case Normalisation::kBest:
      return "best";
    case Normalisation::kSpread:
      return "spread";
    case Normalisation::kNone:
      break;
  }
  return "none";
}

std::string TrialStopText(TrialStop stop) {
  return stop == TrialStop::kReachedFraction
             ? "the best trial reached the stop fraction of the best prediction"
             : "the trial limit was reached";
}

TrialAndErrorResult RunTrialAndError(const std::vector<ArchiveElite>& archive,
                                     const RunTrial& run_trial, const TrialAndErrorParams& params) {
  ValidateTrialAndErrorParams(params);
  CheckArchive(archive);
  const Eigen::Index n = static_cast<Eigen::Index>(archive.size());
  const Eigen::Index d = archive.front().descriptor.size();
  // The GP sees distances divided by `scale`; what it predicts is multiplied back.
  GaussianProcessParams gp_params = params.gp;
  double scale = 1;
  Eigen::VectorXd recorded(n);
  for (Eigen::Index i = 0; i < n; ++i) recorded[i] = archive[static_cast<size_t>(i)].distance;
  if (params.normalise == Normalisation::kBest && recorded.maxCoeff() > 0) {
    scale = recorded.maxCoeff();
  } else if (params.normalise == Normalisation::kSpread) {
    const double variance = (recorded.array() - recorded.mean()).square().mean();
    if (variance > 0) gp_params.signal_variance = variance;
  }
  GaussianProcess gp(gp_params);
  TrialAndErrorResult result;
  Eigen::VectorXd mean(n), sd(n);
  // The posterior at every elite (the ITE code's exhaustive search over the archive).
  const auto predict_all = [&] {
    for (Eigen::Index i = 0; i < n; ++i) {
      const GaussianPrediction p =
          gp.Predict(archive[static_cast<size_t>(i)].descriptor, recorded[i] / scale);
      mean[i] = scale * p.mean;
      sd[i] = scale * std::sqrt(p.variance);
    }
    result.max_predicted_mean = mean.maxCoeff();
  };
  predict_all();
  Eigen::MatrixXd tried_at(0, d);
  Eigen::VectorXd measured(0), prior(0);
  while (true) {
    // The stop test comes before each trial, as limbo's loop does (MaxPredictedValue), and
    // needs one trial at least.
    if (result.stop_rule_trials == 0 && !result.trials.empty() &&
        result.trials.back().best >= params.stop_fraction * result.max_predicted_mean) {
      result.stop_rule_trials = static_cast<int>(result.trials.size());
      if (params.stop_rule) {
        result.stop = TrialStop::kReachedFraction;
        break;
      }
    }
    if (static_cast<int>(result.trials.size()) >= params.max_trials) {
      result.stop = TrialStop::kMaxTrials;
      break;
    }
    // UCB; a strict > keeps the lowest index among equals.
    Eigen::Index next = 0;
    double best_ucb = -INFINITY;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double ucb = mean[i] + params.kappa * sd[i];
      if (ucb > best_ucb) {
        best_ucb = ucb;
        next = i;
      }
    }
    Trial t;
    t.elite = static_cast<int>(next);
    t.predicted_mean = mean[next];
    t.predicted_std = sd[next];
    t.distance = run_trial(t.elite);
    if (!std::isfinite(t.distance)) {
      throw InputError("the trial of elite " + std::to_string(t.elite) +
                       " returned a non-finite distance");
    }
    const bool first = result.trials.empty();
    t.best = first ? t.distance : std::max(t.distance, result.trials.back().best);
    t.best_elite =
        first || t.distance > result.trials.back().best ? t.elite : result.trials.back().best_elite;
    result.trials.push_back(t);

    const Eigen::Index k = tried_at.rows();
    tried_at.conservativeResize(k + 1, d);
    tried_at.row(k) = archive[next].descriptor.transpose();
    measured.conservativeResize(k + 1);
    measured[k] = t.distance / scale;
    prior.conservativeResize(k + 1);
    prior[k] = recorded[next] / scale;
    gp.Fit(tried_at, measured, prior);
    predict_all();
  }
  return result;
}

}  // namespace hexgait
