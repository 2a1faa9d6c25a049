#include "run/still_request.h"

#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "movie/panel_view.h"
#include "render/gl_context.h"
#include "run/runtime_needs.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {

StillSettings MakeStillSettings(const StillRequest& request, const SceneOptions& scene) {
  StillSettings settings;
  ParseSize(request.size, &settings.width, &settings.height);
  if (!(request.time >= 0) || request.time > 1e6) {
    throw InputError("--time must be between 0 and 1e6");
  }
  settings.time = request.time;
  settings.camera = MakeCameraSpec(request.view, "three-quarter", kStillFieldOfView);
  CheckCameraSeesCreature(settings.camera, request.view, settings.width, settings.height);
  settings.cues = MakeCueOptions(request.view);
  CheckMsaa(request.msaa);
  settings.msaa = request.msaa;
  settings.look.overlay = !request.no_overlay;
  settings.look.shadow = !request.no_shadow;
  if (request.time > 0) settings.run = MakeRunOptions(scene, request.time);
  return settings;
}

StillWritten WriteStill(const StillFile& request, const Progress& on_steps) {
  const StillSettings settings = MakeStillSettings(request.still, request.scene);
  const bool to_file = !request.out.empty();
  const SceneAndGenome run = LoadForOutput(request.scene, request.genome, request.out, ".png");
  const Scene& scene = run.scene;
  StillWritten written;
  written.label = run.label;
  written.damage = scene.model.damage;
  if (to_file) CheckExpected(request.expect, request.out);
  RuntimeNeeds needs;
  needs.png = to_file;  // RenderStill makes its renderer before it simulates
  CheckRuntime(needs);
  written.image = RenderStill(scene, run.genome, settings, on_steps);
  if (to_file) WritePng(request.out, written.image);
  if (to_file && !request.expect.empty()) {
    written.expected = CompareWithExpected(request.expect, request.out);
  }
  return written;
}

Image RenderStill(const Scene& scene, const Genome& genome, const StillSettings& settings,
                  const Progress& on_steps) {
  // The GL backend first: a still of a late moment would otherwise simulate for minutes
  // before finding it cannot draw.
  const auto context = GlContext::CreateOrThrow("cannot render");
  std::string error;
  const auto renderer = Renderer::Create(settings.width, settings.height, settings.msaa, &error);
  if (!renderer) throw SystemError("cannot render: " + error);
  SimState state = MakeRestState(scene.model);
  PanelView view(scene.model, scene.program.cycle_period, state, settings.camera, settings.cues);
  view.Sample(state);
  if (settings.time > 0) {
    const RunOptions& run = settings.run;
    MotorController controller(scene.model, scene.program,
                               PerturbedRestLengths(scene.model, scene.program, genome), run.dt);
    PanelViewSampler sampler(view, DefaultSampleSteps(scene.program.cycle_period, run.dt));
    // A still of a late moment simulates for a while first: the caller hears every 65,536
    // steps (a progress bar; Python's signals). The same bits as one Simulate.
    const RunResult result = SimulateInChunks(scene.model, controller, state, run, sampler, 1 << 16,
                                              [&](long long done, long long total) {
                                                if (on_steps) on_steps("steps", done, total);
                                              });
    if (result.diverged) {
      throw InputError(DivergenceMessage(
          result, run, LargestStableStep(scene.model, scene.program, genome, run)));
    }
    view.Sample(state);
  }
  Image image =
      renderer->Render(view.Meshes(state, settings.look),
                       view.ViewProjection(static_cast<float>(settings.width) / settings.height),
                       settings.look.lighting);
  const auto strip_font = MakeStripFont(settings.cues, settings.height, "");
  view.DrawOverlays(image, strip_font.get());
  return image;
}

}  // namespace hexgait
