#include "run/filmstrip_request.h"

#include <algorithm>

#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "run/runtime_needs.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {

FilmstripSettings MakeFilmstripSettings(const FilmstripRequest& request) {
  FilmstripSettings settings;
  ParseSize(request.size, &settings.frame_width, &settings.frame_height);
  if (request.frames < 2 || request.frames > 24) {
    throw InputError("--frames must be between 2 and 24");
  }
  if (request.cycle < 1 || request.cycle > 10000) {
    throw InputError("--cycle must be between 1 and 10000");
  }
  if (static_cast<long long>(settings.frame_width) * request.frames > 16384) {
    throw InputError("--frames x width must be at most 16384 pixels");
  }
  CheckMsaa(request.msaa);
  // Small frames side by side: zoomed in so the legs read (--camera fov=... overrides it).
  settings.camera = MakeCameraSpec(request.view, kFilmstripView, kFilmstripFov);
  if (request.view.track.empty()) settings.camera.tracking = CameraSpec::Tracking::kTrackX;
  CheckCameraSeesCreature(settings.camera, request.view, settings.frame_width,
                          settings.frame_height);
  ViewRequest view = request.view;
  if (view.cues.empty()) view.cues = kFilmstripCues;
  settings.cues = MakeCueOptions(view);
  settings.frames = request.frames;
  settings.cycle = request.cycle;
  settings.msaa_samples = std::max(1, request.msaa);
  settings.look.overlay = false;
  settings.look.shadow = !request.no_shadow;
  return settings;
}

FilmstripResult RenderFilmstrip(const Scene& scene, const SceneOptions& scene_options,
                                const Genome& genome, const FilmstripRequest& request,
                                FilmstripSettings settings, const Progress& on_steps) {
  settings.run = MakeRunOptions(scene_options, request.cycle * scene.program.cycle_period);
  const auto context = GlContext::CreateOrThrow("cannot render");
  return MakeFilmstrip(scene.model, scene.program,
                       PerturbedRestLengths(scene.model, scene.program, genome), settings,
                       on_steps);
}

FilmstripWritten WriteFilmstrip(const FilmstripFile& request, const Progress& on_steps) {
  const FilmstripSettings settings = MakeFilmstripSettings(request.filmstrip);
  const SceneAndGenome run = LoadForOutput(request.scene, request.genome, request.out, ".png");
  CheckExpected(request.expect, request.out);
  FilmstripWritten written;
  written.label = run.label;
  written.damage = run.scene.model.damage;
  RuntimeNeeds needs;
  needs.png = true;
  needs.captions = true;  // every frame's time; the renderer is made before the simulation
  CheckRuntime(needs);
  written.result =
      RenderFilmstrip(run.scene, request.scene, run.genome, request.filmstrip, settings, on_steps);
  WritePng(request.out, written.result.image);
  if (!request.expect.empty()) written.expected = CompareWithExpected(request.expect, request.out);
  return written;
}

}  // namespace hexgait
