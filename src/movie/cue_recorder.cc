#include "movie/cue_recorder.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/trace.h"

namespace hexgait {

CueRecorder::CueRecorder(const CreatureModel& model, double cycle_period)
    : model_(model),
      last_print_(model.legs.size(),
                  Eigen::Vector2f::Constant(std::numeric_limits<float>::infinity())) {
  history_.cycle_period = static_cast<float>(cycle_period);
  history_.num_legs = static_cast<int>(model.legs.size());
  // Footprints a twentieth of the body's length across: visible, yet a step apart.
  float min_x = std::numeric_limits<float>::infinity(), max_x = -min_x;
  for (int b : model.body_particles) {
    min_x = std::min(min_x, static_cast<float>(model.rest_position[b].x()));
    max_x = std::max(max_x, static_cast<float>(model.rest_position[b].x()));
  }
  if (max_x > min_x) history_.foot_radius = 0.05f * (max_x - min_x);
}

void CueRecorder::Sample(const SimState& state) {
  GaitHistory& h = history_;
  h.now = static_cast<float>(state.time);
  // The contact rule of the figures' gait diagram (sim/trace.h).
  const uint32_t down = FeetOnGround(model_, state);
  for (size_t leg = 0; leg < model_.legs.size(); ++leg) {
    const int foot = model_.legs[leg].foot;
    if (!(down >> leg & 1u)) continue;
    if (h.feet_down >> leg & 1u && !h.strip.empty()) continue;  // still down: no new print
    const Eigen::Vector2f at(static_cast<float>(state.x[foot]), static_cast<float>(state.y[foot]));
    // A foot bouncing on one spot makes one print, not several.
    if ((at - last_print_[leg]).norm() < h.foot_radius) continue;
    h.footprints.Push({at, h.now, static_cast<int>(leg)});
    last_print_[leg] = at;
  }
  h.feet_down = down;
  h.strip.Push({h.now, down});
  const Eigen::Vector3d c = BodyCentre(model_, state);
  const Eigen::Vector2f centre(static_cast<float>(c.x()), static_cast<float>(c.y()));
  // A point when the body has moved, so standing still does not use up the ring.
  if (h.trail.empty() || (centre - h.trail.back().at).norm() > 0.2f * h.foot_radius) {
    h.trail.Push({centre, h.now});
  }
}

}  // namespace hexgait
