// Intelligent Trial and Error (Cully, Clune, Tarapore and Mouret, "Robots that adapt like
// animals", Nature 521, 503-507, 2015) as a library loop: a Gaussian process over the
// repertoire's behaviour descriptors, whose prior mean at each elite is the distance the
// repertoire recorded for it, picks the next elite to try by an upper confidence bound, learns
// from what the trial measured, and stops when the best trial reaches a fraction of the best
// prediction. What a trial is (one simulation of an elite's genome on the damaged creature) is
// the caller's: the loop sees elite indices and distances only, so it is tested on synthetic
// archives whose answer is known.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "adapt/gaussian_process.h"
#include "adapt/library_runs.h"

namespace hexgait {

struct ArchiveElite {
  Eigen::VectorXd descriptor;  // in [0, 1]^d (ga/behaviour.h)
  double distance = 0;         // what the repertoire recorded: the prior mean here
};

// How distances meet the GP, whose kernel has a fixed signal variance (docs/model.md, "Adapting
// to damage"). kNone: as they are; beside distances of 0-15 a signal variance of 1 makes UCB's
// exploration term negligible. kBest: divided by the archive's best recorded distance, so the
// prior means lie in [0, 1] as the ITE code's do and the signal variance and kappa are in units
// of the best. kSpread: as they are, with the signal variance set to the variance of the
// archive's recorded distances. Every prediction and trial is reported in distance units.
enum class Normalisation { kNone, kBest, kSpread };
inline constexpr const char* kNormalisationNames = "none, best or spread";
Normalisation ParseNormalisation(const std::string& name);  // throws InputError
std::string NormalisationName(Normalisation normalisation);

// The ITE code's (resibots/ITE, hexa_bomean.cpp) UCB alpha 0.05, MaxPredictedValue ratio 0.9,
// 20 iterations at most and GP noise, but a length scale of 0.15 instead of its 0.4, and
// distances divided by the archive's best: scripts/adapt_gp_study.py measured that the length
// scale decides how far a failed trial's news spreads over the map and so the trade of trials
// for distance, while the normalisation and kappa hardly matter (docs/model.md, "Adapting to
// damage"). IteCodeParams() gives the ITE code's own.
struct TrialAndErrorParams {
  GaussianProcessParams gp{.length_scale = 0.15};
  Normalisation normalise = Normalisation::kBest;
  double kappa = 0.05;         // UCB: mean + kappa * standard deviation
  double stop_fraction = 0.9;  // stop once the best trial >= this times the best prediction
  // false: no stop rule, every one of max_trials trials is run (Cully et al.'s comparisons at a
  // fixed number of trials).
  bool stop_rule = true;
  int max_trials = 20;
};

// The ITE code's settings exactly: length scale 0.4 and distances as they are.
TrialAndErrorParams IteCodeParams();

// Throws InputError: kappa negative or not finite, stop_fraction outside (0, 1], max_trials
// below 1, or the GP's parameters (ValidateGaussianProcessParams).
void ValidateTrialAndErrorParams(const TrialAndErrorParams& params);

// What trials.csv and Python call the prior of the recorded intact distances (Trial::prior -1).
inline constexpr const char* kIntactPriorName = "intact";

struct Trial {
  int elite = -1;
  // The prior mean this trial was chosen under: -1 the archive's recorded distances, k >= 0
  // the library's member k (LibraryRuns::names()).
  int prior = -1;
  double predicted_mean = 0;  // the posterior before this trial
  double predicted_std = 0;
  double distance = 0;  // what the trial measured
  double best = 0;      // the best distance measured so far, this trial included
  int best_elite = -1;  // the elite that measured it
};

enum class TrialStop {
  kReachedFraction,  // the best trial >= stop_fraction x the largest posterior mean
  kMaxTrials,
};
std::string TrialStopText(TrialStop stop);

struct TrialAndErrorResult {
  std::vector<Trial> trials;
  TrialStop stop = TrialStop::kMaxTrials;
  double max_predicted_mean = 0;  // over every elite, after the last trial
  // The trials after which the stop rule first held (the trials run when it is on); 0: it never
  // held within the trials run. With the rule off, what a run with it would have stopped at.
  int stop_rule_trials = 0;
};

// Runs one trial of elite `index` on the damaged creature and says what it measured.
using RunTrial = std::function<TrialMeasure(int index)>;

// A library of damages (adapt/library_runs.h) is a set of candidates for the prior mean when the
// recorded intact distances rank the damaged creature's gaits badly (they correlate 0.08-0.15
// with them on this creature; docs/results.md, "Why the goals are out of reach on these maps").
// After every trial the loop takes as its prior the candidate, the archive itself included,
// whose descriptors at the tried elites lie nearest (least squares) to the descriptors the
// trials showed: the damaged creature's gait diagnoses its damage, as adaptive prior selection
// (Kaushik, Desreumaux and Mouret, Frontiers in Robotics and AI 6:151, 2020) diagnoses it from
// the distances (scripts/adapt_library_study.py measured both). It reads a member's runs at the
// tried elites only where the member could still be the nearest (a member whose gap over the
// runs made already exceeds a candidate's whole gap cannot), and at every elite only for the
// member it takes: the same choice as reading every run, from a fraction of them.
//
// Deterministic: the next elite maximises the UCB, a tie going to the lower index, and so does
// the library's nearest member (the archive first). An elite may be tried again (the GP then
// has two observations of it; the noise keeps the matrix positive definite). Throws InputError
// for an empty archive, descriptors of different lengths or non-finite values, a library of
// another size, or bad parameters; a trial's non-finite distance is refused too, and with a
// library a trial without a finite descriptor of the archive's length.
TrialAndErrorResult RunTrialAndError(const std::vector<ArchiveElite>& archive,
                                     const RunTrial& run_trial, const TrialAndErrorParams& params,
                                     LibraryRuns& library);
TrialAndErrorResult RunTrialAndError(const std::vector<ArchiveElite>& archive,
                                     const RunTrial& run_trial, const TrialAndErrorParams& params);

}  // namespace hexgait
