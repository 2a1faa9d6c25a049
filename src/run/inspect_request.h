// `hexgait inspect`: the creature's structure and the numbers docs/model.md quotes (rigidity,
// natural frequencies, the explicit Euler stability margin of every spring and contact), as one
// call so Python can reach it as the command does.
#pragma once

#include <string>

#include "run/scene.h"

namespace hexgait {

// The report `inspect` prints, for the scene `options` loads (at its --dt). The whole-creature
// analyses are dense eigenvalue problems, cubic in the size: past 100 particles they are skipped
// with a line that says so.
std::string InspectReport(const SceneOptions& options);

}  // namespace hexgait
