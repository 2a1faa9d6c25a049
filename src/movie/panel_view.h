// How one creature is filmed, beyond the creature itself: its camera (spec and tracker) and its
// gait cues (recorder, and what is drawn from it). Shared by movies, stills and filmstrips so
// all three frame and annotate a creature the same way. With no cues on, it holds no history
// and adds nothing to a frame.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "model/creature.h"
#include "movie/cue_recorder.h"
#include "render/camera.h"
#include "render/caption.h"
#include "render/gait_cues.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "sim/state.h"

namespace hexgait {

class PanelView {
 public:
  // `start`: the state the panel's first frame shows (where fixed and track-x cameras stay).
  PanelView(const CreatureModel& model, double cycle_period, const SimState& start,
            const CameraSpec& camera, const CueOptions& cues);

  // Once per frame, in time order: moves the camera and records the cues' history. A second
  // call for the same time changes nothing.
  void Sample(const SimState& state);
  // The meshes of `state` with the scene cues (footprints, trail, swinging legs).
  std::vector<Mesh> Meshes(const SimState& state, const MeshStyle& look) const;
  Eigen::Matrix4f ViewProjection(float aspect) const;
  // Cues drawn into the finished frame (the footfall strip); `strip_font` may be null.
  void DrawOverlays(Image& image, const CaptionFont* strip_font) const;

  // The leg names of the footfall strip's rows, as the figures' gait diagram writes them.
  const std::vector<std::string>& leg_labels() const { return leg_labels_; }

 private:
  const CreatureModel& model_;
  CameraSpec camera_;
  CameraTracker tracker_;
  CueOptions cues_;
  double last_sample_time_ = -1;
  std::unique_ptr<CueRecorder> recorder_;  // null when no cue is on
  std::vector<int> polygon_legs_;
  std::vector<std::string> leg_labels_;
};

// A simulation observer that samples a PanelView every `every_steps` steps, for a frame drawn
// at the end of a run (a still, a filmstrip's panel) to show the cues a movie would.
class PanelViewSampler {
 public:
  PanelViewSampler(PanelView& view, long long every_steps)
      : view_(view), every_(every_steps), until_(every_steps) {}
  void OnStep(const SimState& state) {
    if (--until_ > 0) return;
    until_ = every_;
    view_.Sample(state);
  }

 private:
  PanelView& view_;
  long long every_, until_;
};

// Steps between samples of the camera and cues: one video frame of a default movie (one gait
// cycle per second at 30 frames per second), so stills and filmstrips look like its frames.
long long DefaultSampleSteps(double cycle_period, double dt);

// A font sized for the footfall strip's labels of a frame this high; null when the strip is
// off, too small for labels, or the font cannot be loaded (the strip is then drawn unlabelled).
std::unique_ptr<CaptionFont> MakeStripFont(const CueOptions& cues, int frame_height,
                                           const std::string& font_path);

}  // namespace hexgait
