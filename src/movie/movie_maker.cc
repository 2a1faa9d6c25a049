#include "movie/movie_maker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "motor/controller.h"
#include "movie/panel_view.h"
#include "render/caption.h"
#include "render/leg_colours.h"
#include "render/renderer.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

// One creature being filmed: one run of its simulation from the first frame to the last (never
// restarted, so the movie ends on exactly the state `simulate` computes) and its caption; its
// camera and gait cues are a PanelView.
class PanelRun {
 public:
  PanelRun(const CreatureModel& model, const MotorProgram& program, const MoviePanel& panel,
           const RunOptions& run, int index)
      : model_(model),
        index_(index),
        name_(panel.name),
        notes_(panel.notes),
        controller_(model, program, panel.rest_lengths, run.dt),
        state_(MakeRestState(model)),
        start_x_(BodyCentre(model, state_).x()),
        run_(StartRun(model, controller_, state_, run)) {}

  // Advances by one frame's worth of steps; throws MovieDiverged if the simulation diverges.
  void Advance(long long steps) {
    run_->Advance(steps);
    const RunResult& so_far = run_->result_so_far();
    if (so_far.diverged) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "the simulation of '%s' diverged at t = %.4g (step %lld): ", name_.c_str(),
                    so_far.diverge_time, so_far.diverge_step);
      throw MovieDiverged(index_, so_far, text + so_far.diverge_reason + "; try a smaller --dt");
    }
  }

  std::vector<std::string> Caption() const {
    char line[160];
    std::snprintf(line, sizeof line, "t = %6.1f   cycle %d   distance %5.2f", state_.time,
                  controller_.CycleOf(state_.time), Distance());
    std::vector<std::string> lines = {name_};
    if (!model_.damage.empty()) lines.push_back(DamageNote(model_));
    lines.insert(lines.end(), notes_.begin(), notes_.end());
    lines.emplace_back(line);
    const RunResult& so_far = run_->result_so_far();
    if (so_far.fell) {
      std::snprintf(line, sizeof line, "fell at t = %.0f (cycle %d)", so_far.fall_time,
                    so_far.fall_cycle);
      lines.emplace_back(line);
    }
    return lines;
  }

  double Distance() const { return BodyCentre(model_, state_).x() - start_x_; }
  const SimState& state() const { return state_; }
  // The run's result, exactly as Simulate returns it. Call once, after the last frame.
  RunResult Finish() { return run_->Finish(); }

 private:
  const CreatureModel& model_;
  int index_;
  std::string name_;
  std::vector<std::string> notes_;
  MotorController controller_;
  SimState state_;
  double start_x_;
  std::unique_ptr<ResumableRun> run_;  // last: it refers to controller_ and state_
};

// Copies a panel into its place in the frame, with a dark rule along its top and left edges
// where it borders another panel.
void CopyPanel(const Image& panel, int row, int column, Image& frame) {
  const size_t row_bytes = static_cast<size_t>(panel.width) * 4;
  const size_t frame_row_bytes = static_cast<size_t>(frame.width) * 4;
  const size_t x0 = static_cast<size_t>(column) * row_bytes;
  for (int y = 0; y < panel.height; ++y) {
    uint8_t* out =
        frame.rgba.data() + (static_cast<size_t>(row) * panel.height + y) * frame_row_bytes + x0;
    std::copy_n(panel.rgba.data() + static_cast<size_t>(y) * row_bytes, row_bytes, out);
    if (row > 0 && y < 2) std::fill_n(out, row_bytes, uint8_t{40});
    if (column > 0) std::fill_n(out, 8, uint8_t{40});
  }
}

}  // namespace

long long MovieStepsPerFrame(const MovieSettings& settings, double cycle_period) {
  const double speed = settings.speed > 0 ? settings.speed : cycle_period;
  return std::max(1LL, std::llround(speed / settings.fps / settings.run.dt));
}

long long MovieFrameCount(const MovieSettings& settings, double cycle_period) {
  const long long steps = std::llround(settings.run.duration / settings.run.dt);
  const long long per_frame = MovieStepsPerFrame(settings, cycle_period);
  return (steps + per_frame - 1) / per_frame + 1;  // the last frame may be a shorter step
}

MovieStats MakeMovie(const CreatureModel& model, const MotorProgram& program,
                     const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                     const FrameSink& sink, const Progress& progress) {
  const auto start = Clock::now();
  const int count = static_cast<int>(panels.size());
  const int columns = std::clamp(settings.columns, 1, count);
  const int rows = (count + columns - 1) / columns;
  const int panel_width = settings.width / columns;
  const int panel_height = settings.height / rows;
  std::string error;
  const auto renderer = Renderer::Create(panel_width, panel_height, settings.msaa_samples, &error);
  if (!renderer) throw SystemError("cannot render: " + error);
  // Creating the renderer compiles its shaders (a fraction of a second with a cold cache, more
  // on a loaded machine): a stop asked for meanwhile need not wait for the first frame too.
  if (StopRequested()) throw Stopped("before the first frame; no movie written");
  std::unique_ptr<CaptionFont> font;
  if (settings.caption) {
    // A grid's panels are captioned for their own size; a stack's share the frame's.
    const int size = columns > 1 ? panel_height / 24 : settings.height / 36;
    font = CaptionFont::Create(std::max(10, size), settings.font_path, &error);
    if (!font) throw SystemError("cannot draw captions: " + error);
  }

  std::vector<std::unique_ptr<PanelRun>> runs;
  std::vector<PanelView> views;  // camera and gait cues of each panel
  views.reserve(panels.size());
  for (const MoviePanel& panel : panels) {
    runs.push_back(std::make_unique<PanelRun>(model, program, panel, settings.run,
                                              static_cast<int>(runs.size())));
    views.emplace_back(model, program.cycle_period, runs.back()->state(), settings.camera,
                       settings.cues);
  }
  const std::unique_ptr<CaptionFont> strip_font =
      MakeStripFont(settings.cues, panel_height, settings.font_path);
  const long long steps_per_frame = MovieStepsPerFrame(settings, program.cycle_period);
  const long long total_frames = MovieFrameCount(settings, program.cycle_period);
  const long long total_steps = std::llround(settings.run.duration / settings.run.dt);
  long long steps_done = 0;

  MovieStats stats;
  // Two frames in flight: the finished one goes to the sink (its colour conversion) while the
  // next one's last panel is being drawn, so the two overlap.
  Image frames[2], panel_image;
  for (Image& frame : frames) {
    frame.width = settings.width;
    frame.height = settings.height;
    // Pixels a grid of panels cannot fill (sizes not multiples of the rows and columns, empty
    // places in the last row) stay background.
    frame.rgba.assign(static_cast<size_t>(frame.width) * frame.height * 4, 255);
  }
  Image* finished = nullptr;  // drawn, captioned, not yet given to the sink
  const auto send_finished = [&] {
    if (!finished) return;
    const auto t = Clock::now();
    sink(*finished);
    stats.seconds_sink += SecondsSince(t);
    finished = nullptr;
    ++stats.frames;
    if (progress) progress("frames", stats.frames, total_frames);
  };
  const float aspect = static_cast<float>(panel_width) / static_cast<float>(panel_height);
  const int margin = std::max(4, settings.height / 60);
  for (long long f = 0; f < total_frames; ++f) {
    if (StopRequested()) {
      char text[96];
      std::snprintf(text, sizeof text, "at frame %lld of %lld; no movie written", f, total_frames);
      throw Stopped(text);
    }
    if (f > 0) {
      // The last frame takes the steps left, so the movie ends where `simulate` ends.
      const long long steps = std::min(steps_per_frame, total_steps - steps_done);
      steps_done += steps;
      const auto t = Clock::now();
      try {
        for (auto& run : runs) run->Advance(steps);
      } catch (const MovieDiverged&) {
        send_finished();  // every frame before the divergence reaches the sink
        throw;
      }
      stats.seconds_simulate += SecondsSince(t);
    }
    Image& frame = frames[f % 2];
    for (int p = 0; p < count; ++p) {
      PanelRun& run = *runs[static_cast<size_t>(p)];
      PanelView& view = views[static_cast<size_t>(p)];
      auto t = Clock::now();
      Image& target = count == 1 ? frame : panel_image;
      view.Sample(run.state());
      renderer->Draw(view.Meshes(run.state(), settings.look), view.ViewProjection(aspect),
                     settings.look.lighting);
      stats.seconds_render += SecondsSince(t);
      if (p == count - 1) send_finished();  // while the last panel is drawn
      t = Clock::now();
      renderer->ReadBack(target);
      stats.seconds_render += SecondsSince(t);
      t = Clock::now();
      view.DrawOverlays(target, strip_font.get());
      if (font) font->DrawBox(target, margin, margin, run.Caption());
      if (count > 1) CopyPanel(panel_image, p / columns, p % columns, frame);
      stats.seconds_compose += SecondsSince(t);
    }
    finished = &frame;
  }
  send_finished();
  for (const auto& run : runs) stats.results.push_back(run->Finish());
  stats.seconds_total = SecondsSince(start);
  return stats;
}

}  // namespace hexgait
