// The paper's Figure 1 for the figure set: the creature at rest, springs and particles drawn
// over its polygons, rendered off-screen exactly as 'hexgait still' does.
#pragma once

#include <string>

#include "model/creature.h"
#include "render/camera.h"

namespace hexgait {

// Writes a PNG of `width` x `height` seen by `camera` (the still's default view unless the
// figures command was given --view, --camera or --track); throws InputError when no GL context
// can be made.
void RenderFigure1(const CreatureModel& model, const std::string& path, int width, int height,
                   const CameraSpec& camera = CameraSpec());

}  // namespace hexgait
