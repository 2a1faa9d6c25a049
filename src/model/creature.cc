#include "model/creature.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "util/error.h"

namespace hexgait {

int CreatureModel::LegIndex(const std::string& leg_name) const {
  for (size_t i = 0; i < legs.size(); ++i) {
    if (legs[i].name == leg_name) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Vector3d VertexPosition(const CreatureModel& model, const double* x, const double* y,
                               const double* z, int v) {
  const int n = model.num_particles();
  if (v < n) return {x[v], y[v], z[v]};
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const auto& [i, w] : model.skin_vertices[v - n].blend) {
    p += w * Eigen::Vector3d(x[i], y[i], z[i]);
  }
  return p;
}

bool CreatureModel::particle_loose(int particle) const {
  for (size_t l = 0; l < legs.size(); ++l) {
    if ((lost_legs >> l & 1u) && legs[l].foot == particle) return true;
  }
  return false;
}

std::vector<int> PolygonLegs(const CreatureModel& model) {
  std::vector<int> particle_leg(static_cast<size_t>(model.num_particles()), -1);
  std::vector<char> is_body(static_cast<size_t>(model.num_particles()), 0);
  for (int b : model.body_particles) is_body[b] = 1;
  for (int s = 0; s < model.num_springs(); ++s) {
    const int leg = model.spring_leg[s];
    if (leg < 0) continue;
    for (int p : {model.spring_a[s], model.spring_b[s]}) {
      if (!is_body[p]) particle_leg[p] = leg;
    }
  }
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    particle_leg[model.legs[leg].foot] = static_cast<int>(leg);
  }
  std::vector<double> x, y, z;
  for (const Eigen::Vector3d& p : model.rest_position) {
    x.push_back(p.x()), y.push_back(p.y()), z.push_back(p.z());
  }
  std::vector<int> legs;
  legs.reserve(model.polygons.size());
  for (const Polygon& polygon : model.polygons) {
    int leg = -1;
    if (polygon.is_leg) {
      for (int v : polygon.vertices) {
        if (v < model.num_particles() && particle_leg[v] >= 0) {
          leg = particle_leg[v];
          break;
        }
      }
      if (leg < 0) {  // only skin vertices: the leg whose foot is nearest the polygon's centre
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int v : polygon.vertices)
          centre += VertexPosition(model, x.data(), y.data(), z.data(), v);
        centre /= static_cast<double>(polygon.vertices.size());
        double nearest = INFINITY;
        for (size_t l = 0; l < model.legs.size(); ++l) {
          const double d = (model.rest_position[model.legs[l].foot] - centre).norm();
          if (d < nearest) nearest = d, leg = static_cast<int>(l);
        }
      }
    }
    legs.push_back(leg);
  }
  return legs;
}

void FinalizeCreature(CreatureModel& model, const std::string& source) {
  auto fail = [&](const std::string& what) { throw InputError(source + ": " + what); };
  const int n = model.num_particles();
  if (n < 4) fail("a creature needs at least 4 particles");
  if (model.legs.empty()) fail("a creature needs at least one leg");

  std::vector<bool> is_foot(n, false);
  for (const Leg& leg : model.legs) is_foot[leg.foot] = true;
  model.body_particles.clear();
  for (int i = 0; i < n; ++i) {
    if (!is_foot[i]) model.body_particles.push_back(i);
  }
  if (model.body_particles.size() < 4)
    fail("the body needs at least 4 particles that are not feet");

  // The body's facing comes from its rest pose: +x is forward, +y is left, +z is up.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i : model.body_particles) centre += model.rest_position[i];
  centre /= static_cast<double>(model.body_particles.size());
  model.standing_height = centre.z();
  model.body_front.clear();
  model.body_rear.clear();
  model.body_left.clear();
  model.body_right.clear();
  for (int i : model.body_particles) {
    const Eigen::Vector3d p = model.rest_position[i] - centre;
    if (p.x() > 1e-9) model.body_front.push_back(i);
    if (p.x() < -1e-9) model.body_rear.push_back(i);
    if (p.y() > 1e-9) model.body_left.push_back(i);
    if (p.y() < -1e-9) model.body_right.push_back(i);
  }
  if (model.body_front.empty() || model.body_rear.empty() || model.body_left.empty() ||
      model.body_right.empty()) {
    fail("the body must extend forward, backward, left and right of its centre");
  }
  if (model.standing_height <= model.physics.fall_height) {
    fail("physics.fall_height must be below the standing body height " +
         std::to_string(model.standing_height));
  }

  model.motor_springs.clear();
  for (int s = 0; s < model.num_springs(); ++s) {
    if (model.spring_motor[s]) model.motor_springs.push_back(s);
  }
  for (Leg& leg : model.legs) {
    leg.springs.clear();
    for (int s : model.motor_springs) {
      if (model.legs[model.spring_leg[s]].name == leg.name) leg.springs.push_back(s);
    }
    if (leg.springs.empty()) fail("leg '" + leg.name + "' has no motor springs");
  }
  for (const Leg& leg : model.legs) {
    const Leg& m = model.legs[leg.mirror];
    if (m.mirror < 0 || model.legs[m.mirror].name != leg.name) {
      fail("leg '" + leg.name + "': mirror legs must name each other");
    }
    if (m.springs.size() != leg.springs.size()) {
      fail("leg '" + leg.name + "' and its mirror '" + m.name +
           "' have different numbers of springs");
    }
  }
}

}  // namespace hexgait
