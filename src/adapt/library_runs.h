// The runs of a library of damages (adapt/trial_and_error.h): every elite's distance and the
// descriptor its run showed, on each of the library's damaged creatures. The loop reads a member
// at the elites it has tried (to compare its gaits with the trials') and at every elite only
// when it takes that member as its prior, so the runs are made when first read: a library made
// on demand runs a small part of its members x elites (adapt --library, docs/results.md), and
// one given as tables (Python's trial_and_error) counts the runs it would have made.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hexgait {

// What one trial (or one run of a library) measured: the distance walked and, for a loop with a
// library of damages, the behaviour descriptor the damaged creature's run showed (its duty
// factors: a robot's foot contacts). Implicit from a distance alone, which is all a loop without
// a library reads.
struct TrialMeasure {
  TrialMeasure(double walked) : distance(walked) {}  // NOLINT(google-explicit-constructor)
  TrialMeasure(double walked, Eigen::VectorXd shown)
      : distance(walked), descriptor(std::move(shown)) {}
  double distance = 0;
  Eigen::VectorXd descriptor;  // empty without a library
};

// A damage simulated before the trials, every elite run once on it (library tables).
struct DamageLibraryMember {
  std::string damage;          // its name, for the record
  Eigen::VectorXd distance;    // per elite, on that damaged creature
  Eigen::MatrixXd descriptor;  // elites x dims: what each elite's run on it showed
};

// One run a library needs: elite `elite` on member `member`'s damaged creature.
struct LibraryRun {
  int member = 0;
  int elite = 0;
};

// Makes the runs asked for and returns what each measured, in order (a distance and a
// descriptor). It may run them side by side; what one run measures must not depend on what else
// is asked with it. It may throw to end the work (a stop request).
using RunLibrary = std::function<std::vector<TrialMeasure>(const std::vector<LibraryRun>&)>;

class LibraryRuns {
 public:
  LibraryRuns() = default;  // no library
  // Runs made on demand by `run`, for `names.size()` members of `elites` elites each, with
  // descriptors of `dims` values.
  LibraryRuns(std::vector<std::string> names, int elites, int dims, RunLibrary run);
  // Runs made before: every member's tables, which must be `elites` x `dims` (InputError naming
  // the member otherwise, or a non-finite value); each is read as if it were run then.
  LibraryRuns(std::vector<DamageLibraryMember> tables, int elites, int dims);

  bool empty() const { return names_.empty(); }
  int members() const { return static_cast<int>(names_.size()); }
  int elites() const { return elites_; }
  int dims() const { return dims_; }
  const std::vector<std::string>& names() const { return names_; }

  // Makes whatever of `runs` is not made yet, in one call of the runner (duplicates once).
  // Throws InputError for a run that measured a non-finite distance or a descriptor of
  // another size or with a non-finite value, naming the member and elite.
  void Need(const std::vector<LibraryRun>& runs);
  void NeedMember(int member);  // every elite on `member`
  bool made(int member, int elite) const {
    return made_[static_cast<size_t>(member) * static_cast<size_t>(elites_) +
                 static_cast<size_t>(elite)] != 0;
  }
  // Made runs only.
  const Eigen::VectorXd& distance(int member) const {
    return distance_[static_cast<size_t>(member)];
  }
  const Eigen::MatrixXd& descriptor(int member) const {
    return descriptor_[static_cast<size_t>(member)];
  }
  long long runs_made() const { return runs_made_; }
  long long runs_possible() const { return static_cast<long long>(members()) * elites_; }

 private:
  std::vector<std::string> names_;
  int elites_ = 0;
  int dims_ = 0;
  RunLibrary run_;
  std::vector<Eigen::VectorXd> distance_;
  std::vector<Eigen::MatrixXd> descriptor_;
  std::vector<char> made_;  // members x elites
  long long runs_made_ = 0;
};

}  // namespace hexgait
