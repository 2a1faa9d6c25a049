// Micro-benchmarks of one movie frame's rendering (Google Benchmark), built as
// build/hexgait_render_bench and never run as tests:
//   build/hexgait_render_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The frames are those of the default 1280x720 movie of the unoptimised program (three-quarter
// camera, shadow, no cues), so the numbers are the `render` command's per-frame costs without
// the encoder beside them. docs/speed.md quotes them.
#include <benchmark/benchmark.h>

#include <time.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "motor/assets.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "movie/panel_view.h"
#include "render/gl_context.h"
#include "render/meshes.h"
#include "render/renderer.h"
#include "sim/step_loop.h"

namespace hexgait {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

// 120 states of the first 120 frames (4 s) of the default movie, and the views that film them.
struct Frames {
  CreatureModel model = LoadCreatureOrDefault("");
  MotorProgram program = LoadMotorProgramOrDefault("", model);
  std::vector<SimState> states;
  std::vector<Eigen::Matrix4f> view_projections;
  MeshStyle look;

  Frames() {
    RunOptions run;
    run.duration = 4.0 * program.cycle_period;
    MotorController controller(model, program, GeometricRestLengths(model, program), run.dt);
    SimState state = MakeRestState(model);
    const auto stepped = StartRun(model, controller, state, run);
    PanelView view(model, program.cycle_period, state, CameraSpec(), CueOptions());
    const long long steps = std::llround(program.cycle_period / 30.0 / run.dt);
    for (int f = 0; f < 120; ++f) {
      if (f > 0) stepped->Advance(steps);
      view.Sample(state);
      states.push_back(state);
      view_projections.push_back(view.ViewProjection(static_cast<float>(kWidth) / kHeight));
    }
  }
};

// CPU time of the whole process (llvmpipe's rasterizer threads included), in ms.
double ProcessCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

const Frames& DefaultFrames() {
  static const Frames frames;
  return frames;
}

// One GL context for the process (as a movie has), on the backend named by HEXGAIT_GL if set.
const GlContext& Context() {
  static const std::unique_ptr<GlContext> context = [] {
    std::string error;
    auto made = GlContext::Create(&error);
    if (!made) throw std::runtime_error(error);
    return made;
  }();
  return *context;
}

// Scene meshes + draw + read back of one frame: the `render + read back` stage of a movie.
void BM_RenderFrame(benchmark::State& state) {
  Context();
  const Frames& frames = DefaultFrames();
  std::string error;
  const auto renderer = Renderer::Create(kWidth, kHeight, static_cast<int>(state.range(0)), &error);
  if (!renderer) {
    state.SkipWithError(error.c_str());
    return;
  }
  Image image;
  size_t f = 0;
  const double cpu_start = ProcessCpuMs();
  for (auto _ : state) {
    const std::vector<Mesh> meshes = BuildMeshes(frames.model, frames.states[f], frames.look);
    renderer->Render(meshes, frames.view_projections[f], frames.look.lighting, image);
    benchmark::DoNotOptimize(image.rgba.data());
    f = (f + 1) % frames.states.size();
  }
  state.SetItemsProcessed(state.iterations());
  // What a frame costs the machine: on two cores beside x264, CPU time is what a movie pays.
  state.counters["process_cpu_ms"] =
      (ProcessCpuMs() - cpu_start) / static_cast<double>(state.iterations());
  state.SetLabel(Context().Describe());
}
BENCHMARK(BM_RenderFrame)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();

// Building the meshes alone (CPU, no GL).
void BM_BuildScene(benchmark::State& state) {
  const Frames& frames = DefaultFrames();
  size_t f = 0;
  for (auto _ : state) {
    const std::vector<Mesh> meshes = BuildMeshes(frames.model, frames.states[f], frames.look);
    benchmark::DoNotOptimize(meshes.data());
    f = (f + 1) % frames.states.size();
  }
}
BENCHMARK(BM_BuildScene)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace hexgait

BENCHMARK_MAIN();
