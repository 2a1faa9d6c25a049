#include "model/creature_io.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

// Loose physical bounds: far outside any sensible creature, but keep 1/mass, spring forces and
// rest lengths finite so bad numbers fail here and not as a NaN mid-run.
constexpr double kMinMass = 1e-6;
constexpr double kMaxMass = 1e6;
constexpr double kMaxCoordinate = 1e6;
constexpr double kMaxStiffness = 1e12;
// A skin vertex's weights: generous for extrapolation, small enough to stay finite.
constexpr double kMaxSkinWeight = 1000;

int ParticleIndex(const JsonReader& r, int num_particles) {
  const int i = r.AsInteger();
  if (i < 0 || i >= num_particles) {
    r.Fail("particle index " + std::to_string(i) + " out of range (the creature has " +
           std::to_string(num_particles) + " particles, 0.." + std::to_string(num_particles - 1) +
           ")");
  }
  return i;
}

PhysicsConstants ReadPhysics(const JsonReader& r) {
  r.RequireOnlyKeys({"gravity", "ground_stiffness", "ground_damping", "friction", "slip_velocity",
                     "fall_height", "fall_tilt_degrees"});
  PhysicsConstants p;
  p.gravity = r.NonNegativeNumber("gravity");
  p.ground_stiffness = r.PositiveNumber("ground_stiffness");
  p.ground_damping = r.NonNegativeNumber("ground_damping");
  p.friction = r.NonNegativeNumber("friction");
  p.slip_velocity = r.PositiveNumber("slip_velocity");
  p.fall_height = r.NonNegativeNumber("fall_height");
  p.fall_tilt_degrees = r.PositiveNumber("fall_tilt_degrees");
  if (p.fall_tilt_degrees >= 180) r.Child("fall_tilt_degrees").Fail("must be below 180");
  return p;
}

}  // namespace

CreatureModel ParseCreature(const std::string& json_text, const std::string& source) {
  const nlohmann::json doc = ParseJson(json_text, source);
  const JsonReader root(doc, source, "");
  root.RequireOnlyKeys({"name", "description", "physics", "particles", "legs", "springs",
                        "polygons", "skin_vertices"});
  CreatureModel model;
  model.name = root.String("name");
  model.physics = ReadPhysics(root.Child("physics"));

  const JsonReader particles = root.Child("particles");
  const size_t np = particles.ArraySize();
  if (np < 4 || np > 1000)
    particles.Fail("expected 4 to 1000 particles, got " + std::to_string(np));
  std::set<std::string> particle_names;  // a set: n log n, where a scan would be n^2
  for (size_t i = 0; i < np; ++i) {
    const JsonReader p = particles.At(i);
    p.RequireOnlyKeys({"name", "position", "mass"});
    const std::string name = p.String("name");
    if (!particle_names.insert(name).second) {
      p.Child("name").Fail("duplicate particle name '" + name + "'");
    }
    model.particle_names.push_back(name);
    const double mass = p.PositiveNumber("mass");
    // A denormal mass would make 1/mass infinite and the first step non-finite.
    if (!(mass >= kMinMass && mass <= kMaxMass)) {
      p.Child("mass").Fail("must be between 1e-6 and 1e6, got " + std::to_string(mass));
    }
    model.mass.push_back(mass);
    model.inv_mass.push_back(1.0 / mass);
    const JsonReader pos = p.Child("position");
    if (pos.ArraySize() != 3) pos.Fail("expected [x, y, z]");
    model.rest_position.emplace_back(pos.At(0).AsNumber(), pos.At(1).AsNumber(),
                                     pos.At(2).AsNumber());
    if (model.rest_position.back().z() < 0) pos.Fail("particle starts below the ground (z < 0)");
    // Distances between particles must stay finite (no overflow to inf in the rest lengths).
    if (model.rest_position.back().cwiseAbs().maxCoeff() > kMaxCoordinate) {
      pos.Fail("coordinates must be within +-1e6");
    }
  }
  const int n = static_cast<int>(np);

  const JsonReader legs = root.Child("legs");
  std::vector<std::string> mirror_names;
  std::set<int> feet;
  if (legs.ArraySize() > static_cast<size_t>(kMaxLegs)) {
    legs.Fail("at most " + std::to_string(kMaxLegs) + " legs, got " +
              std::to_string(legs.ArraySize()));
  }
  for (size_t i = 0; i < legs.ArraySize(); ++i) {
    const JsonReader l = legs.At(i);
    l.RequireOnlyKeys({"name", "foot", "side", "mirror"});
    Leg leg;
    leg.name = l.String("name");
    if (model.LegIndex(leg.name) >= 0) l.Fail("duplicate leg name '" + leg.name + "'");
    leg.foot = ParticleIndex(l.Child("foot"), n);
    if (!feet.insert(leg.foot).second)
      l.Fail("two legs share foot particle " + std::to_string(leg.foot));
    const std::string side = l.String("side");
    if (side == "right") {
      leg.side = Side::kRight;
    } else if (side == "left") {
      leg.side = Side::kLeft;
    } else {
      l.Child("side").Fail("expected \"left\" or \"right\", got \"" + side + "\"");
    }
    mirror_names.push_back(l.String("mirror"));
    model.legs.push_back(leg);
  }
  for (size_t i = 0; i < model.legs.size(); ++i) {
    model.legs[i].mirror = model.LegIndex(mirror_names[i]);
    if (model.legs[i].mirror < 0) {
      legs.At(i).Child("mirror").Fail("no leg named '" + mirror_names[i] + "'");
    }
    if (model.legs[model.legs[i].mirror].side == model.legs[i].side) {
      legs.At(i).Child("mirror").Fail("a leg's mirror must be on the other side");
    }
  }

  const JsonReader springs = root.Child("springs");
  std::set<std::pair<int, int>> seen;
  std::set<std::string> spring_names;
  for (size_t i = 0; i < springs.ArraySize(); ++i) {
    const JsonReader s = springs.At(i);
    s.RequireOnlyKeys({"name", "ends", "stiffness", "damping", "leg", "motor"});
    const JsonReader ends = s.Child("ends");
    if (ends.ArraySize() != 2) ends.Fail("expected two particle indices");
    const int a = ParticleIndex(ends.At(0), n);
    const int b = ParticleIndex(ends.At(1), n);
    if (a == b) ends.Fail("a spring cannot join particle " + std::to_string(a) + " to itself");
    if (!seen.insert({std::min(a, b), std::max(a, b)}).second) {
      ends.Fail("duplicate spring between particles " + std::to_string(a) + " and " +
                std::to_string(b));
    }
    const double length = (model.rest_position[a] - model.rest_position[b]).norm();
    if (!(length > 1e-6)) ends.Fail("the two ends start at the same position");
    int leg = -1;
    if (!s.Has("leg")) {
      s.Fail("missing field 'leg' (a leg name, or null for a body spring)");
    } else if (!s.value().at("leg").is_null()) {
      const std::string leg_name = s.String("leg");
      leg = model.LegIndex(leg_name);
      if (leg < 0) s.Child("leg").Fail("no leg named '" + leg_name + "'");
      if (a != model.legs[leg].foot && b != model.legs[leg].foot) {
        s.Child("leg").Fail("a leg spring must end at its leg's foot");
      }
    }
    const bool motor = s.Bool("motor");
    if (motor && leg < 0) s.Child("motor").Fail("a motor spring must belong to a leg");
    const std::string name = s.String("name");
    // Genome files name genes by spring, so names must be unique.
    if (!spring_names.insert(name).second) {
      s.Child("name").Fail("duplicate spring name '" + name + "'");
    }
    model.spring_names.push_back(name);
    model.spring_a.push_back(a);
    model.spring_b.push_back(b);
    const double stiffness = s.PositiveNumber("stiffness");
    if (stiffness > kMaxStiffness) {
      s.Child("stiffness").Fail("must be at most 1e12, got " + std::to_string(stiffness));
    }
    model.stiffness.push_back(stiffness);
    model.damping.push_back(s.NonNegativeNumber("damping"));
    model.rest_length.push_back(length);
    model.spring_leg.push_back(leg);
    model.spring_motor.push_back(motor ? 1 : 0);
  }
  if (model.spring_a.empty()) springs.Fail("a creature needs springs");
  // A particle tied to no spring falls through the creature, held by nothing but the ground:
  // always a mistake in the file.
  std::vector<char> tied(static_cast<size_t>(n), 0);
  for (size_t s = 0; s < model.spring_a.size(); ++s) {
    tied[static_cast<size_t>(model.spring_a[s])] = 1;
    tied[static_cast<size_t>(model.spring_b[s])] = 1;
  }
  for (int i = 0; i < n; ++i) {
    if (!tied[static_cast<size_t>(i)]) {
      particles.At(static_cast<size_t>(i))
          .Fail("particle '" + model.particle_names[static_cast<size_t>(i)] +
                "' is tied to no spring");
    }
  }

  // Skin vertices: optional, rendering only. Each is an affine blend of 1 to 8 distinct
  // particles whose weights sum to 1 (negative weights extrapolate).
  if (root.Has("skin_vertices")) {
    const JsonReader skins = root.Child("skin_vertices");
    const size_t ns = skins.ArraySize();
    if (ns > 10000) skins.Fail("expected at most 10000 skin vertices, got " + std::to_string(ns));
    for (size_t i = 0; i < ns; ++i) {
      const JsonReader sv = skins.At(i);
      sv.RequireOnlyKeys({"name", "blend"});
      SkinVertex skin;
      skin.name = sv.String("name");
      const JsonReader blend = sv.Child("blend");
      const size_t terms = blend.ArraySize();
      if (terms < 1 || terms > 8) {
        blend.Fail("expected 1 to 8 [particle, weight] terms, got " + std::to_string(terms));
      }
      std::set<int> used;
      double sum = 0;
      for (size_t k = 0; k < terms; ++k) {
        const JsonReader term = blend.At(k);
        if (term.ArraySize() != 2) term.Fail("expected [particle index, weight]");
        const int particle = ParticleIndex(term.At(0), n);
        if (!used.insert(particle).second) {
          term.Fail("particle " + std::to_string(particle) + " appears twice in one blend");
        }
        const double weight = term.At(1).AsNumber();
        if (!std::isfinite(weight) || std::abs(weight) > kMaxSkinWeight) {
          term.At(1).Fail("weight must be a finite number within +-" +
                          std::to_string(static_cast<int>(kMaxSkinWeight)));
        }
        sum += weight;
        skin.blend.emplace_back(particle, weight);
      }
      if (std::abs(sum - 1.0) > 1e-9) {
        char text[96];
        std::snprintf(text, sizeof text, "weights sum to %.12g; they must sum to 1 (within 1e-9)",
                      sum);
        blend.Fail(text);
      }
      model.skin_vertices.push_back(std::move(skin));
    }
  }
  const int num_vertices = n + static_cast<int>(model.skin_vertices.size());

  const JsonReader polygons = root.Child("polygons");
  for (size_t i = 0; i < polygons.ArraySize(); ++i) {
    const JsonReader p = polygons.At(i);
    p.RequireOnlyKeys({"vertices", "part"});
    Polygon poly;
    const JsonReader vertices = p.Child("vertices");
    if (vertices.ArraySize() < 3) vertices.Fail("a polygon needs at least 3 vertices");
    for (size_t k = 0; k < vertices.ArraySize(); ++k) {
      const JsonReader vertex = vertices.At(k);
      const int v = vertex.AsInteger();
      if (v < 0 || v >= num_vertices) {
        vertex.Fail("vertex index " + std::to_string(v) + " out of range (the creature has " +
                    std::to_string(n) + " particles and " +
                    std::to_string(model.skin_vertices.size()) + " skin vertices, 0.." +
                    std::to_string(num_vertices - 1) + ")");
      }
      poly.vertices.push_back(v);
    }
    const std::string part = p.String("part");
    if (part != "body" && part != "leg") p.Child("part").Fail("expected \"body\" or \"leg\"");
    poly.is_leg = part == "leg";
    model.polygons.push_back(std::move(poly));
  }

  FinalizeCreature(model, source);
  return model;
}

CreatureModel LoadCreatureFile(const std::string& path) {
  return ParseCreature(ReadTextFile(path), path);
}

}  // namespace hexgait
