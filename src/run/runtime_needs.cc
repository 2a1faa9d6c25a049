#include "run/runtime_needs.h"

#include "encode/video_encoder.h"
#include "render/caption.h"
#include "render/gl_context.h"
#include "render/render_libraries.h"
#include "render/renderer.h"
#include "report/gnuplot.h"
#include "util/error.h"

namespace hexgait {

RuntimeNeeds& RuntimeNeeds::operator|=(const RuntimeNeeds& other) {
  if (other.gl) gl = other.gl;
  png = png || other.png;
  movie = movie || other.movie;
  captions = captions || other.captions;
  figures = figures || other.figures;
  return *this;
}

RuntimeNeeds MovieNeeds(const MovieSettings& settings, bool frames) {
  RuntimeNeeds needs;
  needs.gl = RuntimeNeeds::Drawing{settings.width, settings.height, settings.msaa_samples};
  needs.movie = true;
  needs.captions = settings.caption;
  needs.png = frames;
  return needs;
}

void CheckRuntime(const RuntimeNeeds& needs, const std::string& what) {
  // The cheap lookups first, OpenGL (which may take a second to load its driver) last.
  if (needs.figures) CheckGnuplotFound();
  if (needs.png) Png();
  if (needs.movie) CheckEncoderAvailable();
  if (needs.captions) {
    std::string error;
    if (!CaptionFont::Create(12, "", &error)) throw SystemError("cannot draw captions: " + error);
  }
  if (needs.gl) {
    const auto context = GlContext::CreateOrThrow(what);
    std::string error;
    if (!Renderer::Create(needs.gl->width, needs.gl->height, needs.gl->msaa, &error)) {
      throw SystemError(what + ": " + error);
    }
  }
}

}  // namespace hexgait
