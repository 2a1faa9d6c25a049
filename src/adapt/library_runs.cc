#include "adapt/library_runs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "util/error.h"

namespace hexgait {

LibraryRuns::LibraryRuns(std::vector<std::string> names, int elites, int dims, RunLibrary run)
    : names_(std::move(names)), elites_(elites), dims_(dims), run_(std::move(run)) {
  distance_.assign(names_.size(), Eigen::VectorXd::Zero(elites));
  descriptor_.assign(names_.size(), Eigen::MatrixXd::Zero(elites, dims));
  made_.assign(names_.size() * static_cast<size_t>(elites), 0);
}

LibraryRuns::LibraryRuns(std::vector<DamageLibraryMember> tables, int elites, int dims) {
  for (const DamageLibraryMember& m : tables) {
    if (m.distance.size() != elites || m.descriptor.rows() != elites ||
        m.descriptor.cols() != dims) {
      throw InputError(
          "the library's member '" + m.damage + "' has " + std::to_string(m.distance.size()) +
          " distances and a " + std::to_string(m.descriptor.rows()) + "x" +
          std::to_string(m.descriptor.cols()) + " descriptor table, not " + std::to_string(elites) +
          " and " + std::to_string(elites) + "x" + std::to_string(dims));
    }
    if (!m.distance.allFinite() || !m.descriptor.allFinite()) {
      throw InputError("the library's member '" + m.damage + "' has a non-finite value");
    }
  }
  std::vector<std::string> names;
  for (const DamageLibraryMember& m : tables) names.push_back(m.damage);
  // Read as runs, so that a loop on tables counts the runs it would have made.
  auto shared = std::make_shared<std::vector<DamageLibraryMember>>(std::move(tables));
  *this =
      LibraryRuns(std::move(names), elites, dims, [shared](const std::vector<LibraryRun>& runs) {
        std::vector<TrialMeasure> measured;
        for (const LibraryRun& r : runs) {
          const DamageLibraryMember& m = (*shared)[static_cast<size_t>(r.member)];
          measured.emplace_back(m.distance[r.elite], m.descriptor.row(r.elite).transpose());
        }
        return measured;
      });
}

void LibraryRuns::Need(const std::vector<LibraryRun>& runs) {
  std::vector<LibraryRun> missing;
  for (const LibraryRun& r : runs) {
    if (r.member < 0 || r.member >= members() || r.elite < 0 || r.elite >= elites_) {
      throw std::logic_error("LibraryRuns::Need: no run " + std::to_string(r.member) + "/" +
                             std::to_string(r.elite));
    }
    const bool asked = std::any_of(missing.begin(), missing.end(), [&](const LibraryRun& m) {
      return m.member == r.member && m.elite == r.elite;
    });
    if (!made(r.member, r.elite) && !asked) missing.push_back(r);
  }
  if (missing.empty()) return;
  const std::vector<TrialMeasure> measured = run_(missing);
  if (measured.size() != missing.size()) {
    throw std::logic_error("the library's runner returned " + std::to_string(measured.size()) +
                           " runs for " + std::to_string(missing.size()));
  }
  for (size_t i = 0; i < missing.size(); ++i) {
    const LibraryRun& r = missing[i];
    const TrialMeasure& m = measured[i];
    if (!std::isfinite(m.distance) || m.descriptor.size() != dims_ || !m.descriptor.allFinite()) {
      throw InputError("the library's member '" + names_[static_cast<size_t>(r.member)] +
                       "' has a non-finite value or a descriptor of " +
                       std::to_string(m.descriptor.size()) + " values (not " +
                       std::to_string(dims_) + ") at elite " + std::to_string(r.elite));
    }
    distance_[static_cast<size_t>(r.member)][r.elite] = m.distance;
    descriptor_[static_cast<size_t>(r.member)].row(r.elite) = m.descriptor.transpose();
    made_[static_cast<size_t>(r.member) * static_cast<size_t>(elites_) +
          static_cast<size_t>(r.elite)] = 1;
  }
  runs_made_ += static_cast<long long>(missing.size());
}

void LibraryRuns::NeedMember(int member) {
  std::vector<LibraryRun> runs;
  for (int e = 0; e < elites_; ++e) {
    if (!made(member, e)) runs.push_back({member, e});
  }
  Need(runs);
}

}  // namespace hexgait
