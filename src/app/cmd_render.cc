// hexgait render: a gait movie. The simulation hands every step to an observer that renders
// and encodes only when a video frame is due (a few hundred frames for 400,000 steps).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/progress.h"
#include "encode/video_encoder.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "render/scene.h"
#include "sim/evaluate.h"
#include "sim/run.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace hexgait {

namespace {

struct RenderOptions {
  SceneOptions scene;
  GenomeChoice genome;
  double time = kPaperDuration;
  std::string out = "out/gait.mp4";
  std::string size = "1280x720";
  int fps = 30;
  double speed = 0;  // time units per second of video; 0: one gait cycle per second
  bool overlay = false;
};

// Renders a frame every `steps_per_frame` steps; the camera follows the body smoothly.
class MovieObserver {
 public:
  MovieObserver(const CreatureModel& model, Renderer& renderer, VideoEncoder& encoder,
                long long steps_per_frame, long long total_frames, bool overlay)
      : model_(model),
        renderer_(renderer),
        encoder_(encoder),
        steps_per_frame_(steps_per_frame),
        until_(steps_per_frame),
        total_frames_(total_frames),
        bar_("rendering") {
    look_.overlay = overlay;
  }

  void OnStep(const SimState& state) {
    if (--until_ > 0) return;
    until_ = steps_per_frame_;
    Frame(state);
  }

  void Frame(const SimState& state) {
    const Eigen::Vector3f centre = BodyCentre(model_, state).cast<float>();
    // A critically damped follow: the camera eases towards the body instead of jittering with
    // every step of the gait.
    if (!started_) {
      camera_target_ = centre;
      started_ = true;
    }
    camera_target_ += 0.15f * (centre - camera_target_);
    const float aspect = static_cast<float>(renderer_.width()) / renderer_.height();
    encoder_.Add(renderer_.Render(BuildScene(model_, state, look_),
                                  FramingCamera(camera_target_, aspect), Lighting()));
    bar_.Update(
        static_cast<double>(encoder_.frames()) / total_frames_,
        std::to_string(encoder_.frames()) + "/" + std::to_string(total_frames_) + " frames");
  }

 private:
  const CreatureModel& model_;
  Renderer& renderer_;
  VideoEncoder& encoder_;
  long long steps_per_frame_;
  long long until_;
  long long total_frames_;
  SceneLook look_;
  Eigen::Vector3f camera_target_ = Eigen::Vector3f::Zero();
  bool started_ = false;
  ProgressBar bar_;
};

void Run(const RenderOptions& opt) {
  int width = 0, height = 0;
  ParseSize(opt.size, &width, &height);
  const RunOptions run = MakeRunOptions(opt.scene, opt.time);
  if (opt.fps < 1 || opt.fps > 240) throw InputError("--fps must be between 1 and 240");
  if (opt.speed < 0 || !std::isfinite(opt.speed)) throw InputError("--speed must be positive");
  if (width % 2 != 0 || height % 2 != 0) {
    throw InputError("--size " + opt.size + ": yuv420p needs even width and height");
  }
  CheckOutputPath(opt.out, "--out");
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  const double speed = opt.speed > 0 ? opt.speed : scene.program.cycle_period;
  const long long steps_per_frame = std::max(1LL, std::llround(speed / opt.fps / run.dt));
  const long long total_frames = std::llround(opt.time / run.dt) / steps_per_frame + 1;

  std::string error;
  const auto context = GlContext::Create(&error);
  if (!context) throw InputError("cannot render: " + error);
  const auto renderer = Renderer::Create(width, height, &error);
  if (!renderer) throw InputError("cannot render: " + error);
  VideoEncoder encoder(opt.out, width, height, opt.fps);

  MotorController controller(scene.model, scene.program,
                             PerturbedRestLengths(scene.model, scene.program, genome), run.dt);
  SimState state = MakeRestState(scene.model);
  MovieObserver observer(scene.model, *renderer, encoder, steps_per_frame, total_frames,
                         opt.overlay);
  const auto start = std::chrono::steady_clock::now();
  observer.Frame(state);  // the first frame shows the starting pose
  const RunResult result = Simulate(scene.model, controller, state, run, observer);
  if (result.diverged) {
    throw InputError(
        DivergenceMessage(result, run, LargestStableStep(scene.model, scene.program, genome, run)) +
        "; no movie written");
  }
  encoder.Finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s: %lld frames, %dx%d at %d fps (%.1f s of video), %s, in %.1f s\n",
              opt.out.c_str(), encoder.frames(), width, height, opt.fps,
              static_cast<double>(encoder.frames()) / opt.fps, label.c_str(), seconds);
}

}  // namespace

void RegisterRender(CLI::App& app) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a gait movie (H.264 in MP4)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--time", opt->time, "Simulated time (time units)")->capture_default_str();
  cmd->add_option("--out", opt->out, "MP4 file to write")->capture_default_str();
  cmd->add_option("--size", opt->size, "Frame size, WIDTHxHEIGHT (even numbers)")
      ->capture_default_str();
  cmd->add_option("--fps", opt->fps, "Frames per second")->capture_default_str();
  cmd->add_option("--speed", opt->speed,
                  "Simulated time units per second of video (default: one gait cycle per second)");
  cmd->add_flag("--overlay", opt->overlay, "Draw springs and particles over the polygons");
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
