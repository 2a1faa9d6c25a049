// The paper's Figure 1 for the figure set: the creature at rest, springs and particles drawn
// over its polygons, rendered off-screen exactly as 'hexgait still' does.
#pragma once

#include <string>

#include "model/creature.h"

namespace hexgait {

// Writes a PNG of `width` x `height`; throws InputError when no GL context can be made.
void RenderFigure1(const CreatureModel& model, const std::string& path, int width, int height);

}  // namespace hexgait
