// The standard figure of locomotion papers: frames across one gait cycle, side by side in one
// image, all seen by the same camera and each labelled with its time and phase. The frames
// come from ONE simulation from rest, rendered as it passes each frame's time.
#pragma once

#include <functional>
#include <string>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "render/camera.h"
#include "render/gait_cues.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "sim/step_loop.h"
#include "util/progress.h"

namespace hexgait {

struct FilmstripSettings {
  int frames = 6;  // across the cycle, the first at its start
  int cycle = 3;   // 1-based gait cycle shown, past the start-up transient
  int frame_width = 400, frame_height = 300;
  int msaa_samples = 4;  // a figure for print: smooth edges
  RunOptions run;        // step and integrator; the duration is the cycle's
  MeshStyle look;
  CameraSpec camera;
  CueOptions cues;
  std::string font_path;  // empty: DejaVu Sans from the system
};

struct FilmstripResult {
  Image image;
  RunResult run;  // the simulation up to the last frame: distance, fall
};

// Needs a current GL context. Throws InputError when the renderer or font cannot be made, or
// the simulation diverges before the last frame (the message names its time). `on_steps`
// hears (steps done, steps in all) every 65,536 steps of the simulation: a late cycle takes a
// while.
FilmstripResult MakeFilmstrip(const CreatureModel& model, const MotorProgram& program,
                              const RestLengthTable& rest_lengths,
                              const FilmstripSettings& settings, const Progress& on_steps = {});

}  // namespace hexgait
