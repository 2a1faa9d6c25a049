#include "render/meshes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "render/cue_layers.h"

namespace hexgait {
namespace {

Eigen::Vector3f Position(const SimState& s, int i) {
  return {static_cast<float>(s.x[i]), static_cast<float>(s.y[i]), static_cast<float>(s.z[i])};
}

// Newell's method: a robust normal for any planar or slightly non-planar polygon.
Eigen::Vector3f FaceNormal(const std::vector<Eigen::Vector3f>& p) {
  Eigen::Vector3f n = Eigen::Vector3f::Zero();
  for (size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector3f& a = p[i];
    const Eigen::Vector3f& b = p[(i + 1) % p.size()];
    n.x() += (a.y() - b.y()) * (a.z() + b.z());
    n.y() += (a.z() - b.z()) * (a.x() + b.x());
    n.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  const float length = n.norm();
  return length > 0 ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
}

// A planar projected shadow: every creature triangle flattened onto the ground along the light
// direction. It is drawn unlit in one darkened ground colour (the shader keeps the checker
// pattern), so overlapping triangles cannot darken twice and no stencil pass is needed.
Mesh ShadowOf(const Mesh& solid, const MeshStyle& look) {
  // Slightly above the ground so it wins the depth test against the ground plane.
  constexpr float kLift = 0.004f;
  const Eigen::Vector3f& to_light = look.lighting.direction;
  const float lit_ground = look.lighting.ambient + (1.0f - look.lighting.ambient) * to_light.z();
  const Eigen::Vector3f colour = look.ground_colour * (lit_ground * 0.62f);
  Mesh shadow;
  shadow.kind = Mesh::Kind::kShadow;
  shadow.vertices.reserve(solid.vertices.size());
  for (size_t v = 0; v < solid.vertices.size(); v += 9) {
    const Eigen::Vector3f p(solid.vertices[v], solid.vertices[v + 1], solid.vertices[v + 2]);
    const float height = std::max(p.z() - kLift, 0.0f);
    const Eigen::Vector3f on_ground = p - to_light * (height / to_light.z());
    shadow.Add(Eigen::Vector3f(on_ground.x(), on_ground.y(), kLift), Eigen::Vector3f::UnitZ(),
               colour);
  }
  return shadow;
}

}  // namespace

std::vector<Mesh> BuildMeshes(const CreatureModel& model, const SimState& state,
                              const MeshStyle& options) {
  std::vector<Mesh> meshes;
  const Eigen::Vector3f centre = BodyCentre(model, state).cast<float>();

  // Ground: a square of unit checker cells under the creature, moving with it.
  Mesh ground;
  ground.kind = Mesh::Kind::kGround;
  const float half = 30.0f;
  const float cx = std::floor(centre.x()), cy = std::floor(centre.y());
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f corners[4] = {{cx - half, cy - half, 0},
                                      {cx + half, cy - half, 0},
                                      {cx + half, cy + half, 0},
                                      {cx - half, cy + half, 0}};
  for (int i : {0, 1, 2, 0, 2, 3}) ground.Add(corners[i], up, options.ground_colour);
  meshes.push_back(std::move(ground));

  Mesh solid;
  std::vector<Eigen::Vector3f> points;
  // A damaged leg's polygons take the damaged colour, so that a viewer sees which leg is hurt;
  // a lost leg's are drawn with no area, so it is not seen and every polygon keeps its
  // triangles (the cues colour polygons by their place in the mesh).
  const std::vector<int> polygon_legs =
      model.leg_damaged.empty() ? std::vector<int>() : PolygonLegs(model);
  for (size_t p = 0; p < model.polygons.size(); ++p) {
    const Polygon& polygon = model.polygons[p];
    const int leg = polygon_legs.empty() ? -1 : polygon_legs[p];
    points.clear();
    for (int v : polygon.vertices) {  // a particle or a skin vertex (model/creature.h)
      points.push_back(
          VertexPosition(model, state.x.data(), state.y.data(), state.z.data(), v).cast<float>());
    }
    if (leg >= 0 && model.lost_legs >> leg & 1u) std::fill(points.begin(), points.end(), points[0]);
    const Eigen::Vector3f normal = FaceNormal(points);
    const Eigen::Vector3f& colour = leg >= 0 && model.leg_damaged[leg] ? options.damaged_leg_colour
                                    : polygon.is_leg                   ? options.leg_colour
                                                                       : options.body_colour;
    for (size_t k = 1; k + 1 < points.size(); ++k) {  // fan triangulation
      solid.Add(points[0], normal, colour);
      solid.Add(points[k], normal, colour);
      solid.Add(points[k + 1], normal, colour);
    }
  }
  if (options.shadow) meshes.push_back(ShadowOf(solid, options));
  meshes.push_back(std::move(solid));

  if (options.overlay) {
    Mesh lines, dots;
    lines.kind = Mesh::Kind::kLines;
    dots.kind = Mesh::Kind::kPoints;
    const Eigen::Vector3f spring_colour(0.15f, 0.15f, 0.15f), motor_colour(0.75f, 0.10f, 0.10f);
    for (int s = 0; s < model.num_springs(); ++s) {
      if (model.spring_cut(s)) continue;  // a lost leg's
      const Eigen::Vector3f& c = model.spring_motor[s] ? motor_colour : spring_colour;
      lines.Add(Position(state, model.spring_a[s]), up, c);
      lines.Add(Position(state, model.spring_b[s]), up, c);
    }
    for (int i = 0; i < model.num_particles(); ++i) {
      if (model.particle_loose(i)) continue;  // a lost leg's foot
      dots.Add(Position(state, i), up, Eigen::Vector3f(0.05f, 0.05f, 0.05f));
    }
    meshes.push_back(std::move(lines));
    meshes.push_back(std::move(dots));
  }
  return meshes;
}

}  // namespace hexgait
