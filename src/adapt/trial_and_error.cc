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

// The candidate for the prior (-1 the archive, k >= 0 the library's member k) whose descriptors at
// the tried elites lie nearest, in summed squares, to those the trials showed; the first of
// equals. The archive's gap is known; a member's gap over the runs it has made is a lower bound
// of its whole gap (every term is >= 0, and rounding keeps a partial sum of them below the
// whole), so only members whose bound does not exceed the nearest whole gap so far need their
// missing runs, made a round at a time until none does: the choice of reading every run.
int NearestCandidate(LibraryRuns& library, const Eigen::MatrixXd& archive_descriptors,
                     const std::vector<Eigen::Index>& tried, const Eigen::MatrixXd& shown) {
  const auto gap = [&](const Eigen::MatrixXd& descriptors, int member, bool* whole) {
    double sum = 0;
    *whole = true;
    for (size_t j = 0; j < tried.size(); ++j) {
      if (member >= 0 && !library.made(member, static_cast<int>(tried[j]))) {
        *whole = false;
        continue;
      }
      sum += (shown.row(static_cast<Eigen::Index>(j)) - descriptors.row(tried[j])).squaredNorm();
    }
    return sum;
  };
  while (true) {
    bool whole = true;
    int nearest = -1;
    double nearest_gap = gap(archive_descriptors, -1, &whole);
    std::vector<double> bound(static_cast<size_t>(library.members()));
    std::vector<char> known(static_cast<size_t>(library.members()));
    for (int m = 0; m < library.members(); ++m) {
      bool member_whole = true;
      bound[static_cast<size_t>(m)] = gap(library.descriptor(m), m, &member_whole);
      known[static_cast<size_t>(m)] = member_whole;
      if (member_whole && bound[static_cast<size_t>(m)] < nearest_gap) {
        nearest_gap = bound[static_cast<size_t>(m)];
        nearest = m;
      }
    }
    std::vector<LibraryRun> needed;
    for (int m = 0; m < library.members(); ++m) {
      if (known[static_cast<size_t>(m)] || bound[static_cast<size_t>(m)] > nearest_gap) continue;
      for (const Eigen::Index e : tried) {
        if (!library.made(m, static_cast<int>(e))) needed.push_back({m, static_cast<int>(e)});
      }
    }
    if (needed.empty()) return nearest;
    library.Need(needed);
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
  LibraryRuns none;
  return RunTrialAndError(archive, run_trial, params, none);
}

TrialAndErrorResult RunTrialAndError(const std::vector<ArchiveElite>& archive,
                                     const RunTrial& run_trial, const TrialAndErrorParams& params,
                                     LibraryRuns& library) {
  ValidateTrialAndErrorParams(params);
  CheckArchive(archive);
  const Eigen::Index n = static_cast<Eigen::Index>(archive.size());
  const Eigen::Index d = archive.front().descriptor.size();
  if (!library.empty() && (library.elites() != n || library.dims() != d)) {
    throw InputError("the library of damages was made for " + std::to_string(library.elites()) +
                     " elites of " + std::to_string(library.dims()) +
                     " descriptor values, the archive has " + std::to_string(n) + " of " +
                     std::to_string(d));
  }
  // The GP sees distances divided by `scale`; what it predicts is multiplied back.
  GaussianProcessParams gp_params = params.gp;
  double scale = 1;
  Eigen::VectorXd recorded(n);
  Eigen::MatrixXd descriptors(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    recorded[i] = archive[static_cast<size_t>(i)].distance;
    descriptors.row(i) = archive[static_cast<size_t>(i)].descriptor.transpose();
  }
  if (params.normalise == Normalisation::kBest && recorded.maxCoeff() > 0) {
    scale = recorded.maxCoeff();
  } else if (params.normalise == Normalisation::kSpread) {
    const double variance = (recorded.array() - recorded.mean()).square().mean();
    if (variance > 0) gp_params.signal_variance = variance;
  }
  // The prior's candidates: -1 the archive, k the library's member k (every run of which is
  // made once it is taken).
  const auto prior_distance = [&](int member) -> const Eigen::VectorXd& {
    return member < 0 ? recorded : library.distance(member);
  };
  int member = -1;
  GaussianProcess gp(gp_params);
  TrialAndErrorResult result;
  Eigen::VectorXd mean(n), sd(n);
  // The posterior at every elite (the ITE code's exhaustive search over the archive).
  const auto predict_all = [&] {
    const Eigen::VectorXd& prior = prior_distance(member);
    for (Eigen::Index i = 0; i < n; ++i) {
      const GaussianPrediction p =
          gp.Predict(archive[static_cast<size_t>(i)].descriptor, prior[i] / scale);
      mean[i] = scale * p.mean;
      sd[i] = scale * std::sqrt(p.variance);
    }
    result.max_predicted_mean = mean.maxCoeff();
  };
  predict_all();
  std::vector<Eigen::Index> tried;
  Eigen::MatrixXd tried_at(0, d), shown(0, d);
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
    t.prior = member;
    t.predicted_mean = mean[next];
    t.predicted_std = sd[next];
    const TrialMeasure measure = run_trial(t.elite);
    t.distance = measure.distance;
    if (!std::isfinite(t.distance)) {
      throw InputError("the trial of elite " + std::to_string(t.elite) +
                       " returned a non-finite distance");
    }
    if (!library.empty() && (measure.descriptor.size() != d || !measure.descriptor.allFinite())) {
      throw InputError("the trial of elite " + std::to_string(t.elite) +
                       " returned no finite descriptor of " + std::to_string(d) +
                       " values, which a library of damages needs");
    }
    const bool first = result.trials.empty();
    t.best = first ? t.distance : std::max(t.distance, result.trials.back().best);
    t.best_elite =
        first || t.distance > result.trials.back().best ? t.elite : result.trials.back().best_elite;
    result.trials.push_back(t);

    const Eigen::Index k = tried_at.rows();
    tried.push_back(next);
    tried_at.conservativeResize(k + 1, d);
    tried_at.row(k) = descriptors.row(next);
    measured.conservativeResize(k + 1);
    measured[k] = t.distance / scale;
    if (!library.empty()) {
      shown.conservativeResize(k + 1, d);
      shown.row(k) = measure.descriptor.transpose();
      member = NearestCandidate(library, descriptors, tried, shown);
      if (member >= 0) library.NeedMember(member);
    }
    prior.resize(k + 1);
    for (Eigen::Index j = 0; j <= k; ++j) {
      prior[j] = prior_distance(member)[tried[static_cast<size_t>(j)]] / scale;
    }
    gp.Fit(tried_at, measured, prior);
    predict_all();
  }
  return result;
}

}  // namespace hexgait
