#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "embedded_assets.h"
#include "ga/genome_eval.h"
#include "model/creature_io.h"
#include "model/rigidity.h"
#include "test_util.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

// Both built-in creatures: the default (hexapod) and the first design (wedge).
class BuiltInCreature : public testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(All, BuiltInCreature, testing::Values("hexapod", "wedge"),
                         [](const auto& p) { return p.param; });

TEST(DefaultCreature, IsTheHexapod) {
  EXPECT_EQ(test::DefaultCreature().name, "hexapod");
  EXPECT_EQ(LoadCreatureOrDefault("wedge").name, "wedge");
  EXPECT_EQ(BuiltInCreatureList(), "hexapod, wedge");
}

TEST_P(BuiltInCreature, HasThePapersCounts) {
  const CreatureModel m = LoadCreatureOrDefault(GetParam());
  EXPECT_EQ(m.num_particles(), 14);
  EXPECT_EQ(m.num_springs(), 40);
  EXPECT_EQ(6 * m.num_particles(), 84);  // first-order ODEs
  EXPECT_EQ(m.motor_springs.size(), 20u);
  ASSERT_EQ(m.legs.size(), 6u);
  int three = 0, four = 0;
  for (const Leg& leg : m.legs) {
    three += leg.springs.size() == 3;
    four += leg.springs.size() == 4;
  }
  EXPECT_EQ(three, 4);  // front and rear legs
  EXPECT_EQ(four, 2);   // middle legs
  EXPECT_EQ(m.body_particles.size(), 8u);
}

TEST_P(BuiltInCreature, BodyTrussIsRigid) {
  const auto [rank, needed] = BodyTrussRank(LoadCreatureOrDefault(GetParam()));
  EXPECT_EQ(needed, 18);
  EXPECT_EQ(rank, needed);
}

// The requirements for a creature that reads as a hexapod from any camera.
TEST(DefaultCreature, ReadsAsAHexapod) {
  const CreatureModel m = test::DefaultCreature();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (int i : m.body_particles) {
    lo = lo.cwiseMin(m.rest_position[i]);
    hi = hi.cwiseMax(m.rest_position[i]);
  }
  const Eigen::Vector3d size = hi - lo;
  EXPECT_GT(size.x(), size.y()) << "body longer than it is wide";
  EXPECT_GT(size.y(), size.z()) << "body wider than it is tall";
  EXPECT_GT(lo.z(), size.z()) << "body held clearly above the ground (by more than its height)";
  for (const Leg& leg : m.legs) {
    const Eigen::Vector3d& foot = m.rest_position[leg.foot];
    EXPECT_GT(std::abs(foot.y()), hi.y()) << leg.name << ": foot outside the body's width";
    const double side = leg.side == Side::kLeft ? 1.0 : -1.0;
    for (int s : leg.springs) {
      const int body = m.spring_a[s] == leg.foot ? m.spring_b[s] : m.spring_a[s];
      EXPECT_GE(side * m.rest_position[body].y(), 0.0)
          << m.spring_names[s] << ": a leg ties only to its own side or the midline";
    }
  }
}

// The wedge is the first design, kept unchanged. Its front and rear feet stand inside the body's
// width (and their legs cross the body): the test above would fail for it.
TEST(Wedge, FrontAndRearFeetStandInsideTheBodysWidth) {
  const CreatureModel m = LoadCreatureOrDefault("wedge");
  double body_half_width = 0;
  for (int i : m.body_particles) {
    body_half_width = std::max(body_half_width, std::abs(m.rest_position[i].y()));
  }
  int inside = 0;
  for (const Leg& leg : m.legs) inside += std::abs(m.rest_position[leg.foot].y()) < body_half_width;
  EXPECT_EQ(inside, 4);
}

TEST(SkinVertices, HexapodLimbsBlendParticlesAndTaperToTheFoot) {
  const CreatureModel m = test::DefaultCreature();
  const int n = m.num_particles();
  ASSERT_EQ(m.skin_vertices.size(), 36u);  // 6 legs x (3 root + 3 knee)
  std::vector<double> x(n), y(n), z(n);
  for (int i = 0; i < n; ++i) {
    x[i] = m.rest_position[i].x();
    y[i] = m.rest_position[i].y();
    z[i] = m.rest_position[i].z();
  }
  for (const SkinVertex& skin : m.skin_vertices) {
    double sum = 0;
    for (const auto& [i, w] : skin.blend) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-9) << skin.name;
  }
  // Every leg polygon uses skin vertices or the foot, never a body particle directly; every
  // vertex is a particle or a skin vertex.
  int leg_polygons = 0;
  for (const Polygon& p : m.polygons) {
    for (int v : p.vertices) {
      ASSERT_LT(v, n + static_cast<int>(m.skin_vertices.size()));
      if (p.is_leg && v < n) {
        EXPECT_GE(v, 8) << "a leg polygon uses body particle " << v;
      }
    }
    leg_polygons += p.is_leg;
  }
  EXPECT_EQ(leg_polygons, 36);
  // A skin vertex moves with its particles: translating the whole creature translates it.
  const Eigen::Vector3d before = VertexPosition(m, x.data(), y.data(), z.data(), n + 3);
  for (int i = 0; i < n; ++i) x[i] += 2.5;
  const Eigen::Vector3d after = VertexPosition(m, x.data(), y.data(), z.data(), n + 3);
  EXPECT_NEAR(after.x() - before.x(), 2.5, 1e-9);
  EXPECT_NEAR(after.y(), before.y(), 1e-12);
  // A particle index is the particle itself.
  EXPECT_EQ(VertexPosition(m, x.data(), y.data(), z.data(), 2), Eigen::Vector3d(x[2], y[2], z[2]));
}

TEST(Rigidity, DetectsAFlexibleFramework) {
  // A square with one diagonal is rigid in the plane but folds in 3-D: rank 5 of 6.
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(RigidityRank(square, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}), 5);
  // A tetrahedron is rigid: rank 6.
  const std::vector<Eigen::Vector3d> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_EQ(RigidityRank(tet, {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}), 6);
}

TEST_P(BuiltInCreature, IsMirrorSymmetric) {
  const CreatureModel m = LoadCreatureOrDefault(GetParam());
  auto mirrored = [](Eigen::Vector3d p) {
    p.y() = -p.y();
    return p;
  };
  for (const Leg& leg : m.legs) {
    const Leg& other = m.legs[leg.mirror];
    EXPECT_TRUE(m.rest_position[leg.foot].isApprox(mirrored(m.rest_position[other.foot])));
    ASSERT_EQ(leg.springs.size(), other.springs.size());
    // The symmetric genome layout pairs the k-th springs of mirror legs: they must be mirror
    // images (body ends mirrored, same stiffness and damping).
    for (size_t k = 0; k < leg.springs.size(); ++k) {
      const int s = leg.springs[k], t = other.springs[k];
      const int body_s = m.spring_a[s] == leg.foot ? m.spring_b[s] : m.spring_a[s];
      const int body_t = m.spring_a[t] == other.foot ? m.spring_b[t] : m.spring_a[t];
      EXPECT_TRUE(m.rest_position[body_s].isApprox(mirrored(m.rest_position[body_t])))
          << m.spring_names[s] << " vs " << m.spring_names[t];
      EXPECT_EQ(m.stiffness[s], m.stiffness[t]);
      EXPECT_EQ(m.damping[s], m.damping[t]);
    }
  }
}

TEST_P(BuiltInCreature, ExplicitEulerIsStableAtThePapersStep) {
  const CreatureModel m = LoadCreatureOrDefault(GetParam());
  const double dt = 0.0025;
  for (int s = 0; s < m.num_springs(); ++s) {
    const double ma = m.mass[m.spring_a[s]], mb = m.mass[m.spring_b[s]];
    const double reduced = ma * mb / (ma + mb);
    EXPECT_GT(EulerLargestStableStep(m.stiffness[s] / reduced, m.damping[s] / reduced), 1.5 * dt)
        << m.spring_names[s];
  }
  for (double mass : m.mass) {
    EXPECT_GT(
        EulerLargestStableStep(m.physics.ground_stiffness / mass, m.physics.ground_damping / mass),
        1.5 * dt);
  }
}

TEST_P(BuiltInCreature, LinearisedEulerMapIsStableWithMargin) {
  const CreatureModel m = LoadCreatureOrDefault(GetParam());
  EXPECT_LE(LinearisedEulerSpectralRadius(m, 0.0025), 1.0 + 1e-9);
  const double dt_max = LinearisedEulerLargestStableStep(m);
  EXPECT_GT(dt_max, 1.5 * 0.0025);
  // A step past the largest stable one must be flagged unstable: the check can fail.
  EXPECT_GT(LinearisedEulerSpectralRadius(m, 1.2 * dt_max), 1.0 + 1e-9);
}

TEST(EulerStability, MatchesTheDampedOscillatorCriterion) {
  // For x'' = -w^2 x - c x' (underdamped), forward Euler is stable iff dt < c / w^2.
  const double w2 = 100.0, c = 2.0;
  EXPECT_NEAR(EulerLargestStableStep(w2, c), c / w2, 1e-9);
  EXPECT_TRUE(EulerStableOscillator(w2, c, 0.019));
  EXPECT_FALSE(EulerStableOscillator(w2, c, 0.021));
  // Undamped: unstable at any step.
  EXPECT_FALSE(EulerStableOscillator(w2, 0.0, 1e-6));
}

// Applies `edit` to the default creature's JSON and expects ParseCreature to fail with a
// message containing `expected`.
void ExpectCreatureError(const std::function<void(nlohmann::json&)>& edit,
                         const std::string& expected) {
  nlohmann::json doc = nlohmann::json::parse(reinterpret_cast<const char*>(kEmbeddedHexapodJson));
  edit(doc);
  try {
    ParseCreature(doc.dump(), "bad.json");
    FAIL() << "no error; expected one containing '" << expected << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "error must be one line: " << message;
    EXPECT_EQ(message.rfind("bad.json", 0), 0u) << "error must name the file: " << message;
  }
}

TEST(CreatureJson, RejectsBadInput) {
  ExpectCreatureError([](auto& d) { d.erase("physics"); }, "missing field 'physics'");
  ExpectCreatureError([](auto& d) { d["particles"][0].erase("mass"); },
                      "particles[0]: missing field 'mass'");
  ExpectCreatureError([](auto& d) { d["springs"][3]["ends"][1] = 99; },
                      "particle index 99 out of range");
  ExpectCreatureError([](auto& d) { d["particles"][2]["mass"] = -1.0; },
                      "particles[2].mass: must be positive");
  ExpectCreatureError([](auto& d) { d["springs"][0]["stiffness"] = "stiff"; },
                      "expected a number, got string");
  ExpectCreatureError([](auto& d) { d["springs"][0]["ends"][1] = d["springs"][0]["ends"][0]; },
                      "to itself");
  ExpectCreatureError([](auto& d) { d["springs"][1]["ends"] = d["springs"][0]["ends"]; },
                      "duplicate spring");
  ExpectCreatureError([](auto& d) { d["springs"][0]["colour"] = "red"; }, "unknown field 'colour'");
  ExpectCreatureError([](auto& d) { d["polygons"][0]["vertices"][0] = 50; },
                      "polygons[0].vertices[0]: vertex index 50 out of range");
  ExpectCreatureError([](auto& d) { d.erase("skin_vertices"); },
                      "vertex index 14 out of range (the creature has 14 particles and 0 skin");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][2]["blend"][0][1] = 0.5; },
                      "skin_vertices[2].blend: weights sum to");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["blend"][1][0] = 1; },
                      "skin_vertices[0].blend[1]: particle 1 appears twice in one blend");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["blend"][0][0] = 14; },
                      "skin_vertices[0].blend[0][0]: particle index 14 out of range");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["blend"] = nlohmann::json::array(); },
                      "expected 1 to 8 [particle, weight] terms, got 0");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["blend"][0] = {1}; },
                      "skin_vertices[0].blend[0]: expected [particle index, weight]");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["blend"][0][1] = 1e6; },
                      "weight must be a finite number within +-1000");
  ExpectCreatureError([](auto& d) { d["skin_vertices"][0]["colour"] = "red"; },
                      "unknown field 'colour'");
  ExpectCreatureError([](auto& d) { d["legs"][0]["mirror"] = "nobody"; }, "no leg named 'nobody'");
  ExpectCreatureError(
      [](auto& d) {
        for (int i = 0; i < 3; ++i) d["legs"].push_back(d["legs"][0]);
      },
      "legs: at most 8 legs, got 9");
  ExpectCreatureError(
      [](auto& d) {
        d["particles"].push_back({{"name", "loose"}, {"position", {0, 0, 1}}, {"mass", 1.0}});
      },
      "particles[14]: particle 'loose' is tied to no spring");
  ExpectCreatureError([](auto& d) { d["particles"][3]["name"] = d["particles"][0]["name"]; },
                      "duplicate particle name");
  ExpectCreatureError([](auto& d) { d["springs"][5]["name"] = d["springs"][2]["name"]; },
                      "duplicate spring name");
  ExpectCreatureError([](auto& d) { d["physics"]["friction"] = -0.5; },
                      "physics.friction: must not be negative");
  ExpectCreatureError(
      [](auto& d) {
        d["particles"][0]["position"] = {1, 2};
      },
      "expected [x, y, z]");
}

TEST(CreatureJson, RejectsMalformedAndNonFiniteNumbers) {
  const std::string text = reinterpret_cast<const char*>(kEmbeddedHexapodJson);
  // JSON has no NaN literal: a file containing one is malformed, and the line is named.
  std::string with_nan = text;
  with_nan.replace(with_nan.find("\"mass\": ") + 8, 3, "NaN");
  EXPECT_THROW(
      {
        try {
          ParseCreature(with_nan, "nan.json");
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("malformed JSON at line"), std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
  // A number too large for a double parses as infinity: rejected as not finite.
  std::string with_inf = text;
  with_inf.replace(with_inf.find("\"gravity\": ") + 11, 3, "1e999");
  EXPECT_THROW(ParseCreature(with_inf, "inf.json"), InputError);
  EXPECT_THROW(ParseCreature("{", "truncated.json"), InputError);
}

TEST(TextFiles, AUtf8ByteOrderMarkIsNotPartOfTheText) {
  // Editors on Windows start a file with one; a genome file's first word was then unreadable.
  const std::string path = testing::TempDir() + "/bom.json";
  const std::string text = reinterpret_cast<const char*>(kEmbeddedHexapodJson);
  std::ofstream(path, std::ios::binary) << "\xEF\xBB\xBF" << text;
  EXPECT_EQ(ReadTextFile(path), text);
  EXPECT_EQ(LoadCreatureFile(path).stiffness, LoadCreatureOrDefault("hexapod").stiffness);
}

TEST(CreatureJson, RejectsEmptyFilesAndDirectories) {
  const std::string dir = testing::TempDir();
  const std::string empty = dir + "/empty.json";
  std::ofstream(empty).close();
  EXPECT_THROW(LoadCreatureFile(empty), InputError);
  EXPECT_THROW(LoadCreatureFile(dir), InputError);
  EXPECT_THROW(LoadCreatureFile(dir + "/does-not-exist.json"), InputError);
}

TEST_P(BuiltInCreature, AssetFileMatchesTheEmbeddedCopy) {
  const CreatureModel from_file =
      LoadCreatureFile(std::string(HEXGAIT_SOURCE_DIR "/assets/") + GetParam() + ".json");
  const CreatureModel embedded = LoadCreatureOrDefault(GetParam());
  EXPECT_EQ(from_file.stiffness, embedded.stiffness);
  EXPECT_EQ(from_file.mass, embedded.mass);
  EXPECT_EQ(from_file.skin_vertices.size(), embedded.skin_vertices.size());
}

TEST(CreatureJson, ABuiltInNameSelectsTheBuiltInAndAnythingElseIsAFile) {
  try {
    LoadCreatureOrDefault("beetle");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a built-in creature (hexapod, wedge)"),
              std::string::npos)
        << e.what();
  }
  // A file path, even one that names a built-in's asset, is read as a file.
  const CreatureModel from_file =
      LoadCreatureOrDefault(std::string(HEXGAIT_SOURCE_DIR "/assets/wedge.json"));
  EXPECT_EQ(from_file.name, "wedge");
}

}  // namespace
}  // namespace hexgait
