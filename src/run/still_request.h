// One rendered frame as its options describe it (`still`, Python's render_still): by default
// the paper's Figure 1, the creature at rest; at --time T the frame a movie of the same run shows
// at T.
#pragma once

#include <optional>
#include <string>

#include "render/meshes.h"
#include "render/png_io.h"
#include "run/compare_request.h"
#include "run/scene.h"
#include "run/view_request.h"

namespace hexgait {

struct StillRequest {
  double time = 0;  // 0: the rest pose
  std::string size = "1280x720";
  bool no_overlay = false, no_shadow = false;
  int msaa = 0;
  ViewRequest view;  // --view, --camera, --track, --cues
};

struct StillSettings {
  int width = 0, height = 0;
  double time = 0;
  RunOptions run;  // used when time > 0
  CameraSpec camera;
  CueOptions cues;
  MeshStyle look;
  int msaa = 0;
};

// Range-checks every option (throws InputError naming the flag) before any work.
StillSettings MakeStillSettings(const StillRequest& request, const SceneOptions& scene);

// Simulates `genome` to the frame's time and draws it. The camera and cues are sampled as a
// movie's frames would be, so the still matches the movie's frame at that time (footprints of the
// last cycles, a camera easing after the body). A diverged run is an InputError naming the
// largest stable step.
Image RenderStill(const Scene& scene, const Genome& genome, const StillSettings& settings,
                  const Progress& on_steps = {});

// `hexgait still` and Python's render_still: the frame of `genome` in `scene`, written to `out`
// as a PNG (empty: returned only).
struct StillFile {
  SceneOptions scene;
  GenomeChoice genome;
  StillRequest still;
  std::string out = "out/figure1.png";
  std::string expect;  // --expect: the approved PNG the written one must match
};
struct StillWritten {
  Image image;
  std::string label;                      // the genome's name ("unoptimized", "genome FILE")
  std::string damage;                     // the creature's damage as --damage writes it; "" intact
  std::optional<CompareResult> expected;  // with --expect
};
// Every check before any work, in this order: the options, the inputs and the output (its
// extension, its folder), the scene and the genome, libpng and OpenGL; then the frame, written
// atomically. Throws InputError (SystemError for a library or GL backend that cannot load).
StillWritten WriteStill(const StillFile& request, const Progress& on_steps = {});

}  // namespace hexgait
