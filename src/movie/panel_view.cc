#include "movie/panel_view.h"

#include <algorithm>
#include <cmath>

#include "render/cue_layers.h"

namespace hexgait {

PanelView::PanelView(const CreatureModel& model, double cycle_period, const SimState& start,
                     const CameraSpec& camera, const CueOptions& cues)
    : model_(model),
      camera_(camera),
      tracker_(camera.tracking, BodyCentre(model, start).cast<float>()),
      cues_(cues) {
  if (!cues.any()) return;
  recorder_ = std::make_unique<CueRecorder>(model, cycle_period);
  if (cues.swing) polygon_legs_ = PolygonLegs(model);
  for (const Leg& leg : model.legs) {
    std::string name = leg.name;
    std::replace(name.begin(), name.end(), '_', ' ');
    leg_labels_.push_back(name);
  }
}

void PanelView::Sample(const SimState& state) {
  if (state.time == last_sample_time_) return;
  last_sample_time_ = state.time;
  tracker_.Update(BodyCentre(model_, state).cast<float>());
  if (recorder_) recorder_->Sample(state);
}

std::vector<Mesh> PanelView::Meshes(const SimState& state, const MeshStyle& look) const {
  std::vector<Mesh> meshes = BuildMeshes(model_, state, look);
  if (recorder_) {
    AddSceneCues(model_, polygon_legs_, recorder_->history(), cues_, look, meshes);
  }
  return meshes;
}

Eigen::Matrix4f PanelView::ViewProjection(float aspect) const {
  return hexgait::ViewProjection(camera_, tracker_.current(), aspect);
}

void PanelView::DrawOverlays(Image& image, const CaptionFont* strip_font) const {
  if (recorder_ && cues_.strip) {
    DrawFootfallStrip(image, recorder_->history(), leg_labels_, strip_font);
  }
}

long long DefaultSampleSteps(double cycle_period, double dt) {
  return std::max(1LL, std::llround(cycle_period / 30.0 / dt));
}

std::unique_ptr<CaptionFont> MakeStripFont(const CueOptions& cues, int frame_height,
                                           const std::string& font_path) {
  const int pixels = FootfallStripLayoutFor(frame_height).label_pixels;
  if (!cues.strip || pixels == 0) return nullptr;
  std::string error;
  return CaptionFont::Create(pixels, font_path, &error);
}

}  // namespace hexgait
