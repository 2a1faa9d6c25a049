// Why the body is not a box: enumerates mirror-symmetric bracings (docs/model.md, "Body").
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "model/rigidity.h"
#include "test_util.h"

namespace hexgait {
namespace {

using Bar = std::pair<int, int>;

// Groups all bars between `points` into orbits under the mirror y -> -y.
std::vector<std::vector<Bar>> MirrorOrbits(const std::vector<Eigen::Vector3d>& points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> mirror(n, -1);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d m(points[j].x(), -points[j].y(), points[j].z());
      if ((points[i] - m).norm() < 1e-9) mirror[i] = j;
    }
  }
  std::map<Bar, bool> seen;
  std::vector<std::vector<Bar>> orbits;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (seen.count({a, b})) continue;
      const Bar image = {std::min(mirror[a], mirror[b]), std::max(mirror[a], mirror[b])};
      std::vector<Bar> orbit = {{a, b}};
      seen[{a, b}] = true;
      if (image != Bar{a, b}) {
        orbit.push_back(image);
        seen[image] = true;
      }
      orbits.push_back(orbit);
    }
  }
  return orbits;
}

// Counts mirror-symmetric sets of `count` bars containing `required` that are rigid, and the
// best rank reached.
std::pair<int, int> CountRigid(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Bar>& required, size_t count) {
  std::vector<std::vector<Bar>> orbits;
  for (const auto& orbit : MirrorOrbits(points)) {
    bool is_required = false;
    for (const Bar& bar : orbit) {
      for (const Bar& r : required) is_required = is_required || r == bar;
    }
    if (!is_required) orbits.push_back(orbit);
  }
  const int needed = 3 * static_cast<int>(points.size()) - 6;
  int rigid = 0, best = 0;
  for (long mask = 0; mask < (1L << orbits.size()); ++mask) {
    std::vector<Bar> bars = required;
    for (size_t k = 0; k < orbits.size(); ++k) {
      if (mask >> k & 1) bars.insert(bars.end(), orbits[k].begin(), orbits[k].end());
    }
    if (bars.size() != count) continue;
    const int rank = RigidityRank(points, bars);
    best = std::max(best, rank);
    rigid += rank == needed;
  }
  return {rigid, best};
}

TEST(RigiditySearch, NoMirrorSymmetric20BarBracingOfABoxIsRigid) {
  std::vector<Eigen::Vector3d> box;
  for (double z : {0.6, 1.2}) {
    box.push_back({-1, -0.5, z});
    box.push_back({1, -0.5, z});
    box.push_back({1, 0.5, z});
    box.push_back({-1, 0.5, z});
  }
  std::vector<Bar> edges;
  for (int level = 0; level < 2; ++level) {
    for (int i = 0; i < 4; ++i) edges.push_back({4 * level + i, 4 * level + (i + 1) % 4});
  }
  for (int i = 0; i < 4; ++i) edges.push_back({i, i + 4});
  const auto [rigid, best] = CountRigid(box, edges, 20);
  std::printf("box with its 12 edges: %d rigid symmetric 20-bar sets, best rank %d of 18\n", rigid,
              best);
  EXPECT_EQ(rigid, 0);
  EXPECT_EQ(best, 17);
}

TEST(RigiditySearch, TheCarapaceHasRigidMirrorSymmetricBracings) {
  const CreatureModel model = test::DefaultCreature();
  std::vector<Eigen::Vector3d> body;
  for (int i : model.body_particles) body.push_back(model.rest_position[i]);
  const auto [rigid, best] = CountRigid(body, {}, 20);
  std::printf("carapace: %d rigid mirror-symmetric 20-bar sets\n", rigid);
  EXPECT_EQ(best, 18);
  EXPECT_GT(rigid, 0);
}

}  // namespace
}  // namespace hexgait
