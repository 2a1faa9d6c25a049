// The movie loop: simulation -> render -> encode, one frame at a time. Each creature on screen
// (a panel) is advanced by the steps of one video frame, drawn, captioned, and the composed
// frame goes to a sink (the H.264 encoder, or anything else taking frames). Panels are stacked
// top to bottom, or laid out in a grid, and share one clock, so creatures can be compared frame
// by frame.
// Memory is a few frame buffers, whatever the movie's length.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "render/camera.h"
#include "render/gait_cues.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "sim/step_loop.h"
#include "util/error.h"
#include "util/progress.h"

namespace hexgait {

// One creature on screen: the rest-length table its motor program plays, its name, and caption
// lines drawn under the name (what the panel shows, e.g. its duty factors).
struct MoviePanel {
  std::string name;
  RestLengthTable rest_lengths;
  std::vector<std::string> notes = {};
};

struct MovieSettings {
  int width = 1280, height = 720, fps = 30;
  double speed = 0;   // simulated time units per second of video; 0: one gait cycle per second
  RunOptions run;     // step, integrator and duration of the simulation
  MeshStyle look;     // overlay and shadow on or off
  CameraSpec camera;  // every panel is filmed by the same camera spec, each its own tracker
  CueOptions cues;    // gait cues; all off by default
  int msaa_samples = 1;
  std::string preset = "veryfast";  // x264's (encode/video_encoder.h, EncoderSettings)
  int crf = 20;
  bool caption = true;
  std::string font_path;  // empty: DejaVu Sans from the system
  // Panels per row: 1 stacks them top to bottom; more lays them out in a grid, filled row by
  // row (a repertoire's elites side by side).
  int columns = 1;
};

// Where the time went, and what each creature did.
struct MovieStats {
  long long frames = 0;
  double seconds_simulate = 0, seconds_render = 0, seconds_compose = 0, seconds_sink = 0;
  double seconds_total = 0;
  double seconds_encode = 0;       // conversion and encoding, when the caller's sink encodes
  std::vector<RunResult> results;  // per panel: the run's result, exactly as Simulate gives it
};

// Thrown by MakeMovie when a creature's simulation diverges: which panel, and its run so far
// (time, step and reason of the divergence), so the caller can name the largest stable step.
class MovieDiverged : public InputError {
 public:
  MovieDiverged(int panel, RunResult result, const std::string& message)
      : InputError(message), panel_(panel), result_(std::move(result)) {}
  int panel() const { return panel_; }
  const RunResult& result() const { return result_; }

 private:
  int panel_;
  RunResult result_;
};

using FrameSink = std::function<void(const Image&)>;

// Frames of a movie of `duration` with these settings (the first shows the starting pose).
long long MovieFrameCount(const MovieSettings& settings, double cycle_period);
long long MovieStepsPerFrame(const MovieSettings& settings, double cycle_period);

// Renders the movie frame by frame into `sink`. Needs a current GL context (GlContext).
// Throws InputError if the renderer or font cannot be made, MovieDiverged if a simulation
// diverges (naming the creature, the time and the step), Stopped after Ctrl-C or SIGTERM.
MovieStats MakeMovie(const CreatureModel& model, const MotorProgram& program,
                     const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                     const FrameSink& sink, const Progress& progress = nullptr);

}  // namespace hexgait
