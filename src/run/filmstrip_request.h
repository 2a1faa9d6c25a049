// Frames across one gait cycle side by side in one image, as its options describe it
// (`filmstrip`): a locomotion paper's figure (movie/filmstrip.h).
#pragma once

#include <optional>
#include <string>

#include "movie/filmstrip.h"
#include "run/compare_request.h"
#include "run/scene.h"
#include "run/view_request.h"

namespace hexgait {

// A paper's filmstrip: every frame from the same three-quarter view (both sides' legs), the
// camera sliding along x so progress shows against the ground, lifted legs in their colours
// and footprints so each frame's stance can be read.
inline constexpr const char* kFilmstripView = "three-quarter";
inline constexpr const char* kFilmstripCues = "footprints,swing";
inline constexpr float kFilmstripFov = 28.0f;

struct FilmstripRequest {
  int cycle = 3;  // the gait cycle shown, 1 the first
  int frames = 6;
  std::string size = "400x300";  // of each frame
  int msaa = 4;
  bool no_shadow = false;
  ViewRequest view;  // empty fields: the filmstrip's own view, cues and tracking along x
};

// Range-checks every option (throws InputError naming the flag) before any work; the run's
// length is set by RenderFilmstrip, which knows the program's cycle.
FilmstripSettings MakeFilmstripSettings(const FilmstripRequest& request);

// Simulates `genome` to the end of the cycle and draws its frames.
FilmstripResult RenderFilmstrip(const Scene& scene, const SceneOptions& scene_options,
                                const Genome& genome, const FilmstripRequest& request,
                                FilmstripSettings settings, const Progress& on_steps = {});

// `hexgait filmstrip`: a cycle of `genome` in `scene`, written to `out` as one PNG.
struct FilmstripFile {
  SceneOptions scene;
  GenomeChoice genome;
  FilmstripRequest filmstrip;
  std::string out = "out/filmstrip.png";
  std::string expect;  // --expect: the approved PNG the written one must match
};
struct FilmstripWritten {
  FilmstripResult result;
  std::string label;                      // the genome's name ("unoptimized", "genome FILE")
  std::string damage;                     // the creature's damage as --damage writes it; "" intact
  std::optional<CompareResult> expected;  // with --expect
};
// Every check before any work, in this order: the options, the inputs and the output (its
// extension, its folder), the scene and the genome, libpng, FreeType and OpenGL; then the
// frames, written atomically. Throws InputError (SystemError for what cannot load).
FilmstripWritten WriteFilmstrip(const FilmstripFile& request, const Progress& on_steps = {});

}  // namespace hexgait
