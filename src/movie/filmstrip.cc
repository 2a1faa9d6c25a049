#include "movie/filmstrip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include "motor/controller.h"
#include "movie/panel_view.h"
#include "render/caption.h"
#include "render/leg_colours.h"
#include "render/renderer.h"
#include "util/error.h"

namespace hexgait {
namespace {

constexpr int kSeparator = 2;  // pixels of dark rule between frames

// Samples the camera and cues every few steps, and renders the filmstrip's next frame when the
// run reaches its step: a movie's frame clock with irregular frames.
class FilmstripObserver {
 public:
  using DrawFrame = std::function<void(const SimState&)>;
  FilmstripObserver(PanelView& view, long long sample_steps, const std::vector<long long>& steps,
                    const DrawFrame& draw)
      : sampler_(view, sample_steps), view_(view), steps_(steps), draw_(draw) {}
  void OnStep(const SimState& state) {
    sampler_.OnStep(state);
    while (next_ < steps_.size() && state.step >= steps_[next_]) {
      view_.Sample(state);
      draw_(state);
      ++next_;
    }
  }

 private:
  PanelViewSampler sampler_;
  PanelView& view_;
  const std::vector<long long>& steps_;
  DrawFrame draw_;
  size_t next_ = 0;
};

}  // namespace

FilmstripResult MakeFilmstrip(const CreatureModel& model, const MotorProgram& program,
                              const RestLengthTable& rest_lengths,
                              const FilmstripSettings& settings, const Progress& on_steps) {
  const int n = settings.frames, w = settings.frame_width, h = settings.frame_height;
  std::string error;
  const auto renderer = Renderer::Create(w, h, settings.msaa_samples, &error);
  if (!renderer) throw SystemError("cannot render: " + error);
  const auto font = CaptionFont::Create(std::max(10, h / 18), settings.font_path, &error);
  if (!font) throw SystemError("cannot draw captions: " + error);
  const auto strip_font = MakeStripFont(settings.cues, h, settings.font_path);

  // Frame k at the cycle's start plus k/n of a cycle.
  const double period = program.cycle_period, dt = settings.run.dt;
  const double start = (settings.cycle - 1) * period;
  std::vector<long long> steps;
  for (int k = 0; k < n; ++k) steps.push_back(std::llround((start + k * period / n) / dt));

  FilmstripResult result;
  Image& strip = result.image;
  strip.width = n * w + (n - 1) * kSeparator;
  strip.height = h;
  strip.rgba.assign(static_cast<size_t>(strip.width) * h * 4, 40);  // the separators' colour
  for (size_t p = 3; p < strip.rgba.size(); p += 4) strip.rgba[p] = 255;

  MotorController controller(model, program, rest_lengths, dt);
  SimState state = MakeRestState(model);
  PanelView view(model, period, state, settings.camera, settings.cues);
  view.Sample(state);
  Image frame;
  const float aspect = static_cast<float>(w) / static_cast<float>(h);
  const int margin = std::max(4, h / 50);
  int drawn = 0;
  const auto draw = [&](const SimState& s) {
    renderer->Render(view.Meshes(s, settings.look), view.ViewProjection(aspect),
                     settings.look.lighting, frame);
    view.DrawOverlays(frame, strip_font.get());
    char line[64];
    std::snprintf(line, sizeof line, "t = %.1f   phase %d/%d", s.time, drawn, n);
    // The first frame also names a damaged creature's damage (its leg is drawn red).
    if (drawn == 0 && !model.damage.empty()) {
      font->DrawBox(frame, margin, margin, {line, DamageNote(model)});
    } else {
      font->DrawBox(frame, margin, margin, {line});
    }
    const size_t row = static_cast<size_t>(w) * 4, stride = static_cast<size_t>(strip.width) * 4;
    const size_t left = static_cast<size_t>(drawn) * (w + kSeparator) * 4;
    for (int y = 0; y < h; ++y) {
      std::copy_n(frame.rgba.begin() + static_cast<ptrdiff_t>(y * row), row,
                  strip.rgba.begin() + static_cast<ptrdiff_t>(y * stride + left));
    }
    ++drawn;
  };
  FilmstripObserver observer(view, DefaultSampleSteps(period, dt), steps, draw);
  observer.OnStep(state);  // frames at t = 0
  RunOptions run = settings.run;
  run.duration = static_cast<double>(steps.back()) * dt;
  if (steps.back() > 0) {
    result.run = SimulateInChunks(model, controller, state, run, observer, 1 << 16,
                                  [&](long long done, long long total) {
                                    if (on_steps) on_steps("steps", done, total);
                                  });
    if (result.run.diverged) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "the simulation diverged at t = %.4g (step %lld) before the filmstrip's last "
                    "frame: %s; try a smaller --dt",
                    result.run.diverge_time, result.run.diverge_step,
                    result.run.diverge_reason.c_str());
      throw InputError(text);
    }
  }
  while (drawn < n) draw(state);  // rounding left the last frame a step short
  return result;
}

}  // namespace hexgait
