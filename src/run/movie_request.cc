#include "run/movie_request.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "encode/encoder_thread.h"
#include "encode/video_encoder.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "run/runtime_needs.h"
#include "run/work_size.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/output.h"
#include "util/stop_signal.h"

namespace hexgait {

MovieSettings MakeMovieSettings(const MovieRequest& request, const SceneOptions& scene) {
  MovieSettings settings;
  ParseSize(request.size, &settings.width, &settings.height, request.size_flag);
  if (settings.width % 2 != 0 || settings.height % 2 != 0) {
    throw InputError(request.size_flag + " " + request.size +
                     ": yuv420p needs even width and height");
  }
  if (request.fps < 1 || request.fps > 240) throw InputError("--fps must be between 1 and 240");
  if (!std::isfinite(request.speed) || request.speed < 0) {
    throw InputError("--speed must be a positive number of time units per second");
  }
  if (request.speed > 1e6) throw InputError("--speed must be at most 1e6 time units per second");
  CheckMsaa(request.msaa);
  const auto& presets = X264Presets();
  if (std::find(presets.begin(), presets.end(), request.preset) == presets.end()) {
    throw InputError("--preset '" + request.preset +
                     "': not an x264 preset (ultrafast to veryslow)");
  }
  if (request.crf < 0 || request.crf > 51) throw InputError("--crf must be between 0 and 51");
  settings.run = MakeRunOptions(scene, request.time, 1, request.time_flag);
  // A frame advances by whole steps, at least one: a slower --speed would silently be this one.
  const double slowest = settings.run.dt * request.fps;
  if (request.speed > 0 && request.speed < slowest) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "--speed %g is under one step a frame: at --dt %g and --fps %d the slowest is %g "
                  "time units per second",
                  request.speed, settings.run.dt, request.fps, slowest);
    throw InputError(text);
  }
  settings.fps = request.fps;
  settings.speed = request.speed;
  settings.msaa_samples = std::max(1, request.msaa);
  settings.preset = request.preset;
  settings.crf = request.crf;
  settings.look.overlay = request.overlay;
  settings.look.shadow = !request.no_shadow;
  settings.caption = !request.no_caption;
  settings.camera = MakeCameraSpec(request.view);
  CheckCameraSeesCreature(settings.camera, request.view, settings.width, settings.height);
  settings.cues = MakeCueOptions(request.view, request.cues_flag);
  return settings;
}

void RefuseLongMovieSettings(const MovieRequest& request, const MovieSettings& settings,
                             double cycle_period, bool allow_long) {
  char what[160];
  std::snprintf(what, sizeof what, "%s %g at --speed %g and --fps %d", request.time_flag.c_str(),
                request.time, settings.speed > 0 ? settings.speed : cycle_period, request.fps);
  RefuseLongMovie(what, MovieFrameCount(settings, cycle_period), allow_long);
}

EncoderSettings EncoderSettingsOf(const MovieSettings& settings) {
  EncoderSettings encoder;
  encoder.fps = settings.fps;
  encoder.preset = settings.preset;
  encoder.crf = settings.crf;
  return encoder;
}

MovieStats WriteMovie(const std::string& path, const Scene& scene,
                      const std::vector<MoviePanel>& panels, const MovieSettings& settings,
                      const std::string& frames_dir, const Progress& on_frame) {
  VideoEncoder encoder(path, settings.width, settings.height, EncoderSettingsOf(settings));
  EncoderThread encoder_thread(encoder);
  long long frames_written = 0;
  const FrameSink sink = [&](const Image& frame) {
    encoder_thread.Add(frame);
    if (!frames_dir.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05lld.png", frames_written++);
      WritePng(frames_dir + name, frame);
    }
  };
  const auto start = Clock::now();
  MovieStats stats = MakeMovie(scene.model, scene.program, panels, settings, sink, on_frame);
  encoder_thread.Finish();
  stats.seconds_total = SecondsSince(start);
  stats.seconds_encode = encoder_thread.seconds_convert() + encoder.seconds_encode();
  return stats;
}

MovieStats RenderGaitMovie(const std::string& path, const Scene& scene, const Genome& genome,
                           const std::string& label, const MovieSettings& settings,
                           const std::string& frames_dir, const Progress& on_frame) {
  // --frames DIR is the movie's frames alone: a folder replaced whole once the movie is done
  // (no stale frames of a longer movie among them), and gone if it is not.
  RuntimeNeeds needs = MovieNeeds(settings, !frames_dir.empty());
  needs.gl.reset();  // the context is made next
  CheckRuntime(needs);
  std::optional<AtomicDir> frames;
  if (!frames_dir.empty()) frames.emplace(frames_dir, kFramesMarker, "--frames");
  const auto context = GlContext::CreateOrThrow("cannot render");
  // Loading the GL driver takes a while; a stop asked for meanwhile is honoured here.
  if (StopRequested()) throw Stopped("before the first frame; no movie written");
  const MoviePanel panel{label, PerturbedRestLengths(scene.model, scene.program, genome)};
  try {
    MovieStats stats = WriteMovie(path, scene, {panel}, settings,
                                  frames ? frames->temp_path() : std::string(), on_frame);
    if (frames) frames->Commit();
    return stats;
  } catch (const MovieDiverged& e) {
    throw InputError(
        DivergenceMessage(e.result(), settings.run,
                          LargestStableStep(scene.model, scene.program, genome, settings.run)) +
        "; no movie written");
  }
}

GaitMovieWritten WriteGaitMovie(const GaitMovieFile& request, const Progress& on_frame) {
  GaitMovieWritten written;
  written.settings = MakeMovieSettings(request.movie, request.scene);
  SceneAndGenome run =
      LoadForOutput(request.scene, request.genome, request.out, ".mp4", request.out_flag);
  RefuseLongMovieSettings(request.movie, written.settings, run.scene.program.cycle_period,
                          request.scene.allow_long);
  CheckExpected(request.expect, request.out);
  written.label = run.label;
  written.stats = RenderGaitMovie(request.out, run.scene, run.genome, written.label,
                                  written.settings, request.movie.frames_dir, on_frame);
  if (!request.expect.empty()) written.expected = CompareWithExpected(request.expect, request.out);
  written.scene = std::move(run.scene);
  return written;
}

}  // namespace hexgait
