// A browser replay as its options describe it (`replay`, Python's replay_html): the run's
// length, the camera and cues the page opens with, and how densely the run is kept. The page
// keeps one frame per movie frame of a default movie (30 per gait cycle, the rate stills and
// filmstrips sample the camera and cues at), so its frame at a time is the still's and the
// movie's; a run too long for that is decimated to every k-th frame, or refused.
#pragma once

#include <functional>
#include <string>

#include "render/meshes.h"
#include "run/scene.h"
#include "run/view_request.h"
#include "sim/step_loop.h"

namespace hexgait {

// The most frames one page holds (each about 260 bytes of base64): about 2.4 MB of frames.
inline constexpr long long kReplayMaxFrames = 9000;
// The sparsest decimation accepted: every 6th movie frame, 5 frames per gait cycle. Sparser
// than that a step is no longer visible, so a longer run is refused.
inline constexpr int kReplayMaxStride = 6;

struct ReplayRequest {
  double time = kPaperDuration;
  bool no_overlay = false, no_shadow = false;
  ViewRequest view;  // --view, --camera, --track, --cues: what the page opens with
};

struct ReplaySettings {
  RunOptions run;
  std::string view;  // the preset's name
  CameraSpec camera;
  CueOptions cues;
  MeshStyle look;
  long long every_steps = 0;  // steps per movie frame
  int stride = 1;             // kept frames: one per `stride` movie frames
  long long frames = 0;       // kept frames
  std::string decimation;     // empty, or the one-line message saying what was dropped
};

// Range-checks every option and sizes the page (throws InputError naming the flag): a run
// longer than kReplayMaxFrames movie frames is decimated, one longer than kReplayMaxStride
// times that is refused.
ReplaySettings MakeReplaySettings(const ReplayRequest& request, const SceneOptions& options,
                                  const Scene& scene);

// The longest run a page holds for this scene's cycle and step (kReplayMaxStride x
// kReplayMaxFrames movie frames): a movie set's replays stop there when its movies go on.
double LongestReplay(const Scene& scene, double dt);

// Simulates `genome` and returns the page. `label` names the program ("unoptimized",
// "genome FILE"). A diverged run is an InputError naming the largest stable step; a stop
// (util/stop_signal.h) is honoured within milliseconds.
std::string ReplayHtml(const Scene& scene, const Genome& genome, const ReplaySettings& settings,
                       const std::string& label, const Progress& on_steps = {});

// Throws InputError naming `flag` when `path` is a file hexgait did not write as a replay page
// (no generator line of hexgait's): an HTML file of someone else's is never replaced.
void RefuseForeignPage(const std::string& path, const std::string& flag);

// `hexgait replay`: one run's page written to `out`. With `run_dir`, that evolve run's
// best.genome on the run's own scene (run/folder_scene.h).
struct ReplayFile {
  SceneOptions scene;
  GenomeChoice genome;
  std::string run_dir;
  ReplayRequest replay;
  std::string out = "out/replay.html";
};
struct ReplayWritten {
  ReplaySettings settings;
  std::string label;  // the genome's name
  size_t bytes = 0;
};
// Every check before any work, in this order: --run against --genome, the inputs and the
// output (its extension, its folder, not another program's page), the scene and its options,
// the genome; then the page, written atomically. `on_decimated` gets the one line saying what
// a long run's page leaves out, before the simulation.
ReplayWritten WriteReplay(const ReplayFile& request, const LogLine& on_decimated,
                          const Progress& on_steps = {});

}  // namespace hexgait
