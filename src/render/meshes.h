// Turns a simulation state into what the renderer draws: the creature's polygons (per-face
// normals recomputed from the particles every frame), the ground, and optionally the paper's
// Figure 1 overlay of springs and particles. Cameras are in camera.h.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/creature.h"
#include "render/leg_colours.h"
#include "render/renderer.h"
#include "sim/state.h"

namespace hexgait {

struct MeshStyle {
  bool overlay = true;  // springs and particles drawn over the polygons (Figure 1)
  bool shadow = true;   // the creature's polygons projected onto the ground along the light
  Eigen::Vector3f body_colour = Eigen::Vector3f(0.80f, 0.52f, 0.25f);
  Eigen::Vector3f leg_colour = Eigen::Vector3f(0.30f, 0.45f, 0.70f);
  Eigen::Vector3f damaged_leg_colour = DamagedLegColour();  // a leg the creature's damage hurts
  Eigen::Vector3f ground_colour = Eigen::Vector3f(0.93f, 0.93f, 0.90f);
  Lighting lighting;
};

std::vector<Mesh> BuildMeshes(const CreatureModel& model, const SimState& state,
                              const MeshStyle& options);

}  // namespace hexgait
