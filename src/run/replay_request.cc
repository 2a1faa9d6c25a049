#include "run/replay_request.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "movie/panel_view.h"
#include "render/leg_colours.h"
#include "replay/replay_page.h"
#include "replay/replay_recording.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/run_state.h"
#include "sim/evaluate.h"
#include "util/error.h"
#include "util/output.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

std::string NumberText(double value, const char* format = "%g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// The movie frames a run of `steps` steps is kept as: one every `every_steps`, with the start
// and the end. The limit and the page's size both count them this way.
long long MovieFramesOf(long long steps, long long every_steps) {
  return steps / every_steps + 2;
}

}  // namespace

double LongestReplay(const Scene& scene, double dt) {
  const long long every_steps = DefaultSampleSteps(scene.program.cycle_period, dt);
  // The most movie frames at the sparsest stride, less the start and the end (MovieFramesOf).
  const long long frames = kReplayMaxStride * kReplayMaxFrames - MovieFramesOf(0, every_steps);
  return std::floor(static_cast<double>(frames * every_steps) * dt);
}

ReplaySettings MakeReplaySettings(const ReplayRequest& request, const SceneOptions& options,
                                  const Scene& scene) {
  ReplaySettings settings;
  if (!(request.time > 0) || request.time > 1e6) {
    throw InputError("--time must be greater than 0 and at most 1e6");
  }
  // The page frames the creature as a still does; the mouse wheel backs away from it.
  settings.view = request.view.view.empty() ? "three-quarter" : request.view.view;
  settings.camera = MakeCameraSpec(request.view, "three-quarter", kStillFieldOfView);
  CheckCameraSeesCreature(settings.camera, request.view, 16, 9);
  settings.cues = MakeCueOptions(request.view);
  settings.look.overlay = !request.no_overlay;
  settings.look.shadow = !request.no_shadow;
  settings.run = MakeRunOptions(options, request.time);
  const double period = scene.program.cycle_period;
  settings.every_steps = DefaultSampleSteps(period, settings.run.dt);
  const long long steps = std::llround(settings.run.duration / settings.run.dt);
  const long long movie_frames = MovieFramesOf(steps, settings.every_steps);
  settings.stride = static_cast<int>((movie_frames + kReplayMaxFrames - 1) / kReplayMaxFrames);
  const double frame_time = settings.every_steps * settings.run.dt;
  if (settings.stride > kReplayMaxStride) {
    throw InputError("--time " + NumberText(request.time) + ": a replay holds at most " +
                     NumberText(static_cast<double>(kReplayMaxFrames)) +
                     " frames at 5 or more per gait cycle, so at most " +
                     NumberText(LongestReplay(scene, settings.run.dt)) +
                     " time units; replay a shorter run");
  }
  settings.frames = (movie_frames + settings.stride - 1) / settings.stride;
  if (settings.stride > 1) {
    settings.decimation = "replay: " + NumberText(static_cast<double>(movie_frames)) +
                          " movie frames are more than a page holds (" +
                          NumberText(static_cast<double>(kReplayMaxFrames)) + "): keeping one in " +
                          NumberText(settings.stride) + ", " +
                          NumberText(period / (frame_time * settings.stride), "%.1f") +
                          " frames per gait cycle";
  }
  return settings;
}

std::string ReplayHtml(const Scene& scene, const Genome& genome, const ReplaySettings& settings,
                       const std::string& label, const Progress& on_steps) {
  const RunOptions& run = settings.run;
  SimState state = MakeRestState(scene.model);
  ReplayRecorder recorder(scene.model, scene.program.cycle_period, state, settings.every_steps,
                          settings.stride, static_cast<size_t>(settings.frames));
  recorder.Sample(state, true);
  MotorController controller(scene.model, scene.program,
                             PerturbedRestLengths(scene.model, scene.program, genome), run.dt);
  // A long replay simulates for seconds before writing anything: a stop (Ctrl-C) is honoured,
  // and the caller hears, every 16,384 steps (a few milliseconds).
  const auto between_chunks = [&](long long done, long long total) {
    if (StopRequested()) throw Stopped("during the run; no page written");
    if (on_steps) on_steps("steps", done, total);
  };
  const RunResult result =
      SimulateInChunks(scene.model, controller, state, run, recorder, 1 << 14, between_chunks);
  if (result.diverged) {
    throw InputError(
        DivergenceMessage(result, run, LargestStableStep(scene.model, scene.program, genome, run)));
  }
  recorder.Sample(state, true);
  const ReplayRecording recording = recorder.Finish(result);

  ReplayPageOptions page;
  page.title = scene.model.damage.empty() ? label : label + " (" + DamageNote(scene.model) + ")";
  page.summary = scene.model.name + ", " + IntegratorName(run.integrator) + " at dt " +
                 NumberText(run.dt) + ": walked " + NumberText(result.distance, "%.3f") + " in " +
                 NumberText(run.duration) + " time units" +
                 (result.fell ? ", fell at t = " + NumberText(result.fall_time, "%.1f") +
                                    " (cycle " + NumberText(result.fall_cycle) + ")"
                              : ", did not fall");
  page.cycle_period = scene.program.cycle_period;
  page.duration = run.duration;
  page.dt = run.dt;
  page.view = settings.view;
  page.camera = settings.camera;
  page.preset_fov = kStillFieldOfView;
  page.cues = settings.cues;
  page.look = settings.look;
  return ReplayPage(scene.model, recording, page);
}

void RefuseForeignPage(const std::string& path, const std::string& flag) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return;  // a new name (CheckOutputPath says whether it can be written)
  // The generator line is in the page's first lines (assets/replay/page.html).
  std::string head(1024, '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(file.gcount()));
  if (head.find("<meta name=\"generator\" content=\"hexgait replay\">") == std::string::npos) {
    throw InputError(flag + " '" + path +
                     "': a file hexgait did not write as a replay page; give a new name (or "
                     "remove it)");
  }
}

ReplayWritten WriteReplay(const ReplayFile& request, const LogLine& on_decimated,
                          const Progress& on_steps) {
  SceneOptions scene_options = request.scene;
  GenomeChoice genome_choice = request.genome;
  if (!request.run_dir.empty()) {
    if (!genome_choice.path.empty() || genome_choice.unoptimized) {
      throw InputError(
          "--run replays that run's best.genome: give --run, --genome or --unoptimized, not two");
    }
    IoPaths().Input("--run", request.run_dir).Check();
    genome_choice.path = FinishedRunGenome(request.run_dir, "--run");
    scene_options = SceneOfFolders(scene_options, {{"--run", request.run_dir}});
  }
  const SceneAndGenome run = LoadForOutput(scene_options, genome_choice, request.out, ".html");
  RefuseForeignPage(request.out, "--out");
  const Scene& scene = run.scene;
  const Genome& genome = run.genome;
  ReplayWritten written;
  written.label = run.label;
  written.settings = MakeReplaySettings(request.replay, scene_options, scene);
  if (!written.settings.decimation.empty() && on_decimated) {
    on_decimated(written.settings.decimation);
  }
  const std::string page = ReplayHtml(scene, genome, written.settings, written.label, on_steps);
  WriteFileAtomically(request.out, page);
  written.bytes = page.size();
  return written;
}

}  // namespace hexgait
