// The loop of Intelligent Trial and Error (adapt/trial_and_error.h) on synthetic archives whose
// answer is known: an intact creature stops at once, a "damaged" one finds the region that
// still works in a few trials, ties go to the lower index, and the limits and bad input hold.
#include "adapt/trial_and_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/error.h"

namespace hexgait {
namespace {

// 41 elites on a line in [0, 1] (a 1-D descriptor) that walked 10 + 5x in the repertoire.
std::vector<ArchiveElite> LineArchive() {
  std::vector<ArchiveElite> archive;
  for (int i = 0; i <= 40; ++i) {
    const double x = i / 40.0;
    archive.push_back({Eigen::VectorXd::Constant(1, x), 10 + 5 * x});
  }
  return archive;
}

TEST(TrialAndError, WhenThePriorIsRightItStopsAfterOneTrial) {
  const std::vector<ArchiveElite> archive = LineArchive();
  int calls = 0;
  const TrialAndErrorResult r = RunTrialAndError(
      archive,
      [&](int i) {
        ++calls;
        return archive[i].distance;
      },
      IteCodeParams());
  ASSERT_EQ(r.trials.size(), 1u);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(r.trials[0].elite, 40);  // the best prior; every std is 1 before any trial
  EXPECT_DOUBLE_EQ(r.trials[0].predicted_mean, 15.0);
  EXPECT_DOUBLE_EQ(r.trials[0].predicted_std, 1.0);
  EXPECT_EQ(r.stop, TrialStop::kReachedFraction);
  EXPECT_EQ(r.stop_rule_trials, 1);
  EXPECT_NEAR(r.max_predicted_mean, 15.0, 1e-9);
}

// The "damage" breaks every gait with x >= 0.5 (they walk a tenth of their prior). The first
// trial (x = 1, the best prior) fails by 13.5; the GP's residual pulls the whole line down by
// 13.5 k(r) (l = 0.4), so the UCB moves to x = 0.1, the farthest elite still predicted well,
// which walks its prior, 10.5. Near x = 0.5 the failure still weighs, so nothing is predicted
// above 10.5 / 0.9 and the loop stops: 2 trials, 85% of the best working elite (x = 0.475,
// 12.375), as ITE's stopping rule (90% of the best prediction, not of the truth) allows.
TEST(TrialAndError, FindsTheRegionThatStillWorksInAFewTrials) {
  const std::vector<ArchiveElite> archive = LineArchive();
  const auto damaged = [&](int i) {
    const double x = archive[i].descriptor[0];
    return x >= 0.5 ? 0.1 * archive[i].distance : archive[i].distance;
  };
  const TrialAndErrorResult r = RunTrialAndError(archive, damaged, IteCodeParams());
  EXPECT_EQ(r.stop, TrialStop::kReachedFraction);
  ASSERT_EQ(r.trials.size(), 2u);
  EXPECT_EQ(r.trials[0].elite, 40);
  EXPECT_DOUBLE_EQ(r.trials[0].distance, 1.5);
  EXPECT_EQ(r.trials[1].elite, 4);
  EXPECT_DOUBLE_EQ(r.trials[1].distance, 10.5);
  // Its prediction before the trial: the prior 10.5 less the failure's pull at r = 0.9.
  GaussianProcessParams gp;
  const double pull = Matern52(0.9, gp) / (Matern52(0, gp) + gp.noise) * (1.5 - 15.0);
  EXPECT_NEAR(r.trials[1].predicted_mean, 10.5 + pull, 1e-12);
  const Trial& last = r.trials.back();
  EXPECT_EQ(last.best_elite, 4);
  EXPECT_GE(last.best, 0.9 * r.max_predicted_mean);
  EXPECT_LT(r.max_predicted_mean, 12.375);
  // The record: best-so-far never falls, and each best_elite measured that best.
  for (size_t k = 0; k < r.trials.size(); ++k) {
    const Trial& t = r.trials[k];
    EXPECT_EQ(t.best, damaged(t.best_elite));
    if (k > 0) {
      EXPECT_GE(t.best, r.trials[k - 1].best);
    }
  }
  // Deterministic: the same trials again.
  const TrialAndErrorResult again = RunTrialAndError(archive, damaged, IteCodeParams());
  ASSERT_EQ(again.trials.size(), r.trials.size());
  for (size_t k = 0; k < r.trials.size(); ++k) EXPECT_EQ(again.trials[k].elite, r.trials[k].elite);
}

// Divided by the archive's best, the GP's units are the best's: the same archive and damage in
// other units of distance give the same trials, with every prediction in those units; before any
// trial the standard deviation is the best distance itself (signal variance 1 in units of it).
TEST(TrialAndError, NormalisedByTheBestItDoesNotDependOnTheUnitOfDistance) {
  TrialAndErrorParams params = IteCodeParams();
  params.normalise = Normalisation::kBest;
  std::vector<ArchiveElite> small = LineArchive(), large = LineArchive();
  for (ArchiveElite& e : large) e.distance *= 10;
  const auto damaged = [](const std::vector<ArchiveElite>& archive) {
    return [&archive](int i) {
      const double x = archive[i].descriptor[0];
      return x >= 0.5 ? 0.1 * archive[i].distance : archive[i].distance;
    };
  };
  const TrialAndErrorResult a = RunTrialAndError(small, damaged(small), params);
  const TrialAndErrorResult b = RunTrialAndError(large, damaged(large), params);
  ASSERT_EQ(a.trials.size(), b.trials.size());
  EXPECT_DOUBLE_EQ(a.trials[0].predicted_std, 15.0);
  for (size_t k = 0; k < a.trials.size(); ++k) {
    EXPECT_EQ(a.trials[k].elite, b.trials[k].elite);
    EXPECT_NEAR(10 * a.trials[k].predicted_mean, b.trials[k].predicted_mean, 1e-9);
    EXPECT_NEAR(10 * a.trials[k].predicted_std, b.trials[k].predicted_std, 1e-9);
  }
  // Unnormalised, the exploration term is a thirtieth of that: another search.
  const TrialAndErrorResult plain = RunTrialAndError(small, damaged(small), IteCodeParams());
  EXPECT_DOUBLE_EQ(plain.trials[0].predicted_std, 1.0);
  EXPECT_EQ(ParseNormalisation(NormalisationName(Normalisation::kBest)), Normalisation::kBest);
  EXPECT_THROW(ParseNormalisation("max"), InputError);
}

// With the spread, the signal variance is the archive's variance of recorded distances.
TEST(TrialAndError, WithTheSpreadTheSignalVarianceIsTheArchivesVariance) {
  const std::vector<ArchiveElite> archive = LineArchive();
  double mean = 0, variance = 0;
  for (const ArchiveElite& e : archive) mean += e.distance / archive.size();
  for (const ArchiveElite& e : archive) {
    variance += (e.distance - mean) * (e.distance - mean) / archive.size();
  }
  TrialAndErrorParams params;
  params.normalise = Normalisation::kSpread;
  const TrialAndErrorResult r = RunTrialAndError(
      archive, [&](int i) { return archive[i].distance; }, params);
  EXPECT_NEAR(r.trials[0].predicted_std, std::sqrt(variance), 1e-12);
  EXPECT_DOUBLE_EQ(r.trials[0].predicted_mean, 15.0);
}

// With no stop rule the loop runs every trial it is given, even when its first is the best.
TEST(TrialAndError, WithoutTheStopRuleItRunsEveryTrial) {
  const std::vector<ArchiveElite> archive = LineArchive();
  TrialAndErrorParams p;
  p.stop_rule = false;
  p.max_trials = 17;
  int calls = 0;
  const TrialAndErrorResult r = RunTrialAndError(
      archive,
      [&](int i) {
        ++calls;
        return archive[i].distance;
      },
      p);
  EXPECT_EQ(calls, 17);
  ASSERT_EQ(r.trials.size(), 17u);
  EXPECT_EQ(r.stop, TrialStop::kMaxTrials);
  EXPECT_EQ(r.trials.back().best, 15.0);  // the first trial's, never beaten
  EXPECT_EQ(r.stop_rule_trials, 1);       // where the rule would have stopped it
}

TEST(TrialAndError, TiesGoToTheLowerIndexAndTheLimitStopsIt) {
  std::vector<ArchiveElite> archive;
  for (int i = 0; i < 5; ++i) archive.push_back({Eigen::Vector2d(0.25 * i, 0.5), 4.0});
  TrialAndErrorParams p = IteCodeParams();
  p.max_trials = 3;
  std::vector<int> tried;
  // Nothing works: the best trial (0) never reaches 90% of a positive prediction.
  const TrialAndErrorResult r = RunTrialAndError(
      archive,
      [&](int i) {
        tried.push_back(i);
        return 0.0;
      },
      p);
  EXPECT_EQ(r.stop, TrialStop::kMaxTrials);
  EXPECT_EQ(r.stop_rule_trials, 0);  // the rule never held
  ASSERT_EQ(tried.size(), 3u);
  EXPECT_EQ(tried[0], 0);  // five equal priors and stds: the lowest index
  EXPECT_EQ(tried[1], 4);  // then the farthest from the failure
  EXPECT_EQ(r.trials.back().best, 0.0);
}

// The damage of FindsTheRegionThatStillWorksInAFewTrials, whose creature also shows each gait's
// descriptor mirrored (x -> 1 - x), and a library of two simulated damages: one that shows x +
// 0.3 and walks 20 everywhere, and the right one. The first trial (x = 1, the intact prior's
// best) shows 0: nearest the right member's 0 (the archive's 1, the other's 1.3), which becomes
// the prior; its best elite (x = 0.475, 12.375) is tried next and the rule holds, where the
// intact prior alone stops at 10.5.
TEST(TrialAndError, ALibraryOfDamagesGivesThePriorTheTrialsLookLike) {
  const std::vector<ArchiveElite> archive = LineArchive();
  const Eigen::Index n = static_cast<Eigen::Index>(archive.size());
  const auto walks = [&](Eigen::Index i) {
    const double x = archive[static_cast<size_t>(i)].descriptor[0];
    return x >= 0.5 ? 0.1 * archive[static_cast<size_t>(i)].distance
                    : archive[static_cast<size_t>(i)].distance;
  };
  DamageLibraryMember other{"other", Eigen::VectorXd::Constant(n, 20), Eigen::MatrixXd(n, 1)};
  DamageLibraryMember right{"right", Eigen::VectorXd(n), Eigen::MatrixXd(n, 1)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = archive[static_cast<size_t>(i)].descriptor[0];
    other.descriptor(i, 0) = x + 0.3;
    right.distance[i] = walks(i);
    right.descriptor(i, 0) = 1 - x;
  }
  const auto trial = [&](int i) {
    return TrialMeasure(walks(i), Eigen::VectorXd::Constant(1, 1 - archive[i].descriptor[0]));
  };
  LibraryRuns two({other, right}, static_cast<int>(n), 1);
  const TrialAndErrorResult r = RunTrialAndError(archive, trial, IteCodeParams(), two);
  ASSERT_EQ(r.trials.size(), 2u);
  EXPECT_EQ(r.trials[0].elite, 40);
  EXPECT_EQ(r.trials[0].prior, -1);  // before any trial: the recorded distances
  EXPECT_EQ(r.trials[1].prior, 1);
  EXPECT_EQ(r.trials[1].elite, 19);
  EXPECT_DOUBLE_EQ(r.trials[1].distance, 12.375);
  EXPECT_NEAR(r.trials[1].predicted_mean, 12.375, 1e-12);  // the first trial was as predicted
  EXPECT_EQ(r.stop, TrialStop::kReachedFraction);

  // A member that shows what the archive records ties with it, and the archive comes first:
  // the same trials as without a library.
  DamageLibraryMember same{"same", Eigen::VectorXd::Zero(n), Eigen::MatrixXd(n, 1)};
  for (Eigen::Index i = 0; i < n; ++i) same.descriptor(i, 0) = archive[i].descriptor[0];
  const auto as_recorded = [&](int i) { return TrialMeasure(walks(i), archive[i].descriptor); };
  LibraryRuns one({same}, static_cast<int>(n), 1);
  const TrialAndErrorResult tied = RunTrialAndError(archive, as_recorded, IteCodeParams(), one);
  const TrialAndErrorResult plain = RunTrialAndError(
      archive, [&](int i) { return walks(i); }, IteCodeParams());
  ASSERT_EQ(tied.trials.size(), plain.trials.size());
  for (size_t k = 0; k < tied.trials.size(); ++k) {
    EXPECT_EQ(tied.trials[k].elite, plain.trials[k].elite);
    EXPECT_EQ(tied.trials[k].prior, -1);
  }

  // A member of another size, a library made for another archive, a trial without its
  // descriptor, a table with a non-finite value and a library run that measured one are
  // refused.
  DamageLibraryMember short_member = right;
  short_member.distance.conservativeResize(n - 1);
  EXPECT_THROW(LibraryRuns({short_member}, static_cast<int>(n), 1), InputError);
  LibraryRuns smaller(std::vector<std::string>{"a"}, static_cast<int>(n) - 1, 1, {});
  EXPECT_THROW(RunTrialAndError(archive, trial, IteCodeParams(), smaller), InputError);
  LibraryRuns right_only({right}, static_cast<int>(n), 1);
  EXPECT_THROW(RunTrialAndError(
                   archive, [&](int i) { return walks(i); }, IteCodeParams(), right_only),
               InputError);
  DamageLibraryMember broken = right;
  broken.descriptor(40, 0) = NAN;
  EXPECT_THROW(LibraryRuns({broken}, static_cast<int>(n), 1), InputError);
  LibraryRuns broken_runs(std::vector<std::string>{"broken"}, static_cast<int>(n), 1,
                          [](const std::vector<LibraryRun>& runs) {
                            return std::vector<TrialMeasure>(runs.size(), TrialMeasure(NAN));
                          });
  EXPECT_THROW(RunTrialAndError(archive, trial, IteCodeParams(), broken_runs), InputError);
}

// A library of eight members on the same creature: each shows the descriptor shifted by its own
// amount and walks its own way; the trials show the fifth's gaits. Made on demand it gives the
// trials of the same library made whole beforehand, asks for no run twice, makes every run of
// each member taken as the prior, and makes far fewer runs than the whole library holds.
TEST(TrialAndError, ALibraryMadeOnDemandMakesOnlyTheRunsTheChoiceReads) {
  const std::vector<ArchiveElite> archive = LineArchive();
  const int n = static_cast<int>(archive.size());
  const auto x_of = [&](int i) { return archive[static_cast<size_t>(i)].descriptor[0]; };
  const auto walks = [&](int member, int i) { return 10 - 8 * std::abs(x_of(i) - member / 8.0); };
  const auto shows = [&](int member, int i) {
    return Eigen::VectorXd::Constant(1, x_of(i) + 0.1 * member);
  };
  std::vector<std::string> names;
  for (int m = 0; m < 8; ++m) names.push_back("member " + std::to_string(m));
  std::vector<std::pair<int, int>> asked;
  const RunLibrary run = [&](const std::vector<LibraryRun>& runs) {
    std::vector<TrialMeasure> measured;
    for (const LibraryRun& r : runs) {
      asked.emplace_back(r.member, r.elite);
      measured.emplace_back(walks(r.member, r.elite), shows(r.member, r.elite));
    }
    return measured;
  };
  const auto trial = [&](int i) { return TrialMeasure(walks(5, i), shows(5, i)); };
  TrialAndErrorParams params;
  params.stop_rule = false;
  params.max_trials = 6;

  LibraryRuns whole(names, n, 1, run);
  for (int m = 0; m < whole.members(); ++m) whole.NeedMember(m);
  const TrialAndErrorResult expected = RunTrialAndError(archive, trial, params, whole);
  asked.clear();
  LibraryRuns on_demand(names, n, 1, run);
  const TrialAndErrorResult got = RunTrialAndError(archive, trial, params, on_demand);

  ASSERT_EQ(got.trials.size(), expected.trials.size());
  for (size_t k = 0; k < got.trials.size(); ++k) {
    EXPECT_EQ(got.trials[k].elite, expected.trials[k].elite) << "trial " << k;
    EXPECT_EQ(got.trials[k].prior, expected.trials[k].prior) << "trial " << k;
    EXPECT_EQ(got.trials[k].predicted_mean, expected.trials[k].predicted_mean) << "trial " << k;
  }
  EXPECT_EQ(got.trials.back().prior, 5);
  std::vector<std::pair<int, int>> once = asked;
  std::sort(once.begin(), once.end());
  EXPECT_EQ(std::unique(once.begin(), once.end()), once.end()) << "a run was asked for twice";
  EXPECT_EQ(on_demand.runs_made(), static_cast<long long>(asked.size()));
  for (int e = 0; e < n; ++e) EXPECT_TRUE(on_demand.made(5, e)) << "elite " << e;
  EXPECT_LT(on_demand.runs_made(), on_demand.runs_possible() / 2);
}

TEST(TrialAndError, RefusesBadInput) {
  const std::vector<ArchiveElite> archive = LineArchive();
  const auto ok = [](int) { return 1.0; };
  EXPECT_THROW(RunTrialAndError({}, ok, {}), InputError);
  std::vector<ArchiveElite> mixed = archive;
  mixed[3].descriptor = Eigen::Vector2d(0.1, 0.2);
  EXPECT_THROW(RunTrialAndError(mixed, ok, {}), InputError);
  for (auto edit : std::vector<void (*)(TrialAndErrorParams&)>{
           [](TrialAndErrorParams& p) { p.kappa = -1; },
           [](TrialAndErrorParams& p) { p.stop_fraction = 0; },
           [](TrialAndErrorParams& p) { p.stop_fraction = 1.5; },
           [](TrialAndErrorParams& p) { p.max_trials = 0; },
           [](TrialAndErrorParams& p) { p.gp.length_scale = 0; }}) {
    TrialAndErrorParams p;
    edit(p);
    EXPECT_THROW(RunTrialAndError(archive, ok, p), InputError);
  }
  EXPECT_THROW(RunTrialAndError(archive, [](int) { return NAN; }, {}), InputError);
}

}  // namespace
}  // namespace hexgait
