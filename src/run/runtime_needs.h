// What a request will load or run besides its inputs (OpenGL, libpng, FFmpeg, FreeType and its
// font, gnuplot), found before the work: one that is missing ends the request at once with a
// SystemError (exit 4; Python's RuntimeError) instead of after hours of evaluation with nothing
// written. Each library is loaded for good (util/shared_library.h), so checking costs nothing
// later.
#pragma once

#include <optional>
#include <string>

#include "movie/movie_maker.h"

namespace hexgait {

struct RuntimeNeeds {
  // Draws with OpenGL: the backend (HEXGAIT_GL) and a renderer of this size and anti-aliasing.
  struct Drawing {
    int width = 0, height = 0, msaa = 1;
  };
  std::optional<Drawing> gl;
  bool png = false;       // reads or writes PNG files: libpng
  bool movie = false;     // encodes MP4: FFmpeg and its libx264 encoder
  bool captions = false;  // draws text: FreeType and the DejaVu Sans font
  bool figures = false;   // draws figures: gnuplot on PATH

  RuntimeNeeds& operator|=(const RuntimeNeeds& other);
};

// What writing a movie of `settings` needs: its renderer, FFmpeg, captions when they are on,
// and libpng when `frames` (--frames) are written too.
RuntimeNeeds MovieNeeds(const MovieSettings& settings, bool frames = false);

// Loads or finds everything `needs` names; throws SystemError starting with `what` for OpenGL
// ("cannot render the movie grid: ...") and naming the library or tool otherwise. An unknown
// HEXGAIT_GL name is an InputError.
void CheckRuntime(const RuntimeNeeds& needs, const std::string& what = "cannot render");

}  // namespace hexgait
