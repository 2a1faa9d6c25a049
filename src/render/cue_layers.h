// Draws the gait cues of gait_cues.h: footprints and the trail as decals on the ground, the
// swinging legs recoloured in the creature's mesh, and the footfall strip into the finished
// frame (on the CPU, like the caption).
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"
#include "render/caption.h"
#include "render/gait_cues.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "render/renderer.h"

namespace hexgait {

// Adds the cues that live in the 3-D scene to the meshes of BuildMeshes: footprints and trail
// as decals just before the creature's polygons, and the swinging legs' polygons in their leg
// colour (`polygon_legs`: model/creature.h's PolygonLegs). Does nothing for cues that are off.
void AddSceneCues(const CreatureModel& model, const std::vector<int>& polygon_legs,
                  const GaitHistory& history, const CueOptions& cues, const MeshStyle& look,
                  std::vector<Mesh>& meshes);

// The footfall strip's geometry for a frame of this height: row height and label font size
// (0: too small for labels).
struct FootfallStripLayout {
  int row_height = 4;
  int label_pixels = 0;
};
FootfallStripLayout FootfallStripLayoutFor(int image_height);

// Draws the gait diagram of the last few cycles along the bottom of `image`: one row per leg
// (leg colours, the order and names of `figures`' gait diagram), a bar where the foot is down,
// time running right to left so "now" stays at the right end, thin ticks at cycle boundaries.
// `labels` (leg names) are drawn with `font` when it is not null.
void DrawFootfallStrip(Image& image, const GaitHistory& history,
                       const std::vector<std::string>& labels, const CaptionFont* font);

}  // namespace hexgait
