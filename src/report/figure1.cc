#include "report/figure1.h"

#include "render/gl_context.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "sim/state.h"
#include "util/error.h"

namespace hexgait {

void RenderFigure1(const CreatureModel& model, const std::string& path, int width, int height,
                   const CameraSpec& camera) {
  const auto context = GlContext::CreateOrThrow("cannot render Figure 1");
  // A single frame for print: 4x MSAA smooths the edges for a few milliseconds more.
  std::string error;
  const auto renderer = Renderer::Create(width, height, 4, &error);
  if (!renderer) throw SystemError("cannot render Figure 1: " + error);
  const SimState rest = MakeRestState(model);
  MeshStyle look;
  look.overlay = true;
  // At rest every tracking mode looks at the body centre.
  const Eigen::Vector3f target = BodyCentre(model, rest).cast<float>();
  const Image image = renderer->Render(
      BuildMeshes(model, rest, look),
      ViewProjection(camera, target, static_cast<float>(width) / height), look.lighting);
  WritePng(path, image);
}

}  // namespace hexgait
