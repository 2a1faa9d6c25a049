#include "app/bench_movie.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/bench_common.h"
#include "app/cli_common.h"
#include "app/movie_options.h"
#include "encode/encoder_thread.h"
#include "encode/video_encoder.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "util/atomic_file.h"
#include "util/child_process.h"
#include "util/error.h"
#include "util/median.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

// Scratch files: removed when this goes, and registered in util/temp_registry meanwhile, so a
// stop removes them too. Each is removed before it is unregistered, so a stop arriving while an
// error unwinds cannot leave one behind.
class ScratchFiles {
 public:
  explicit ScratchFiles(const std::vector<std::string>& paths) : paths_(paths) {
    for (const std::string& path : paths) handles_.push_back(RegisterTemp(path));
  }
  ~ScratchFiles() {
    for (size_t i = 0; i < paths_.size(); ++i) {
      std::remove(paths_[i].c_str());
      UnregisterTemp(handles_[i]);
    }
  }
  ScratchFiles(const ScratchFiles&) = delete;
  ScratchFiles& operator=(const ScratchFiles&) = delete;

 private:
  std::vector<std::string> paths_;
  std::vector<int> handles_;
};

using Clock = std::chrono::steady_clock;

struct BenchMovieOptions {
  SceneOptions scene;
  GenomeChoice genome;
  MovieRequest movie;
  int repeats = 3;
  std::string out_dir = "out/bench";
  bool json = false;
  bool no_ffmpeg = false;
  bool no_memory = false;
};

double Seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Measured {
  std::vector<double> simulate_alone, movie_total, simulate, render, compose, convert, encode,
      pipe_total, encode_only;
  long long frames = 0;
  double movie_bytes = 0;
};

bool HaveFfmpegTool() {
  try {
    ChildProcess probe({"ffmpeg", "-version"}, false);
    return probe.Wait() == 0;
  } catch (const InputError&) {
    return false;
  }
}

void Run(const BenchMovieOptions& opt) {
  const MovieSettings settings = MakeMovieSettings(opt.movie, opt.scene);
  if (opt.repeats < 1 || opt.repeats > 100) throw InputError("--repeats must be 1 to 100");
  // Scratch only: a folder this makes is removed at the end, and the scratch movies are
  // removed if the benchmark is stopped (a memory run's finished movie included).
  const BenchOutDir out(opt.out_dir, "bench_movie.mp4");
  const std::string movie_path = out.path() + "bench_movie.mp4";
  const std::string pipe_path = out.path() + "bench_movie_ffmpeg.mp4";
  const std::string reference_path = out.path() + "bench_movie_reference.mp4";
  const ScratchFiles scratch({movie_path, pipe_path, reference_path});
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  const MoviePanel panel{label, PerturbedRestLengths(scene.model, scene.program, genome)};
  const bool ffmpeg = !opt.no_ffmpeg && HaveFfmpegTool();
  if (!opt.no_ffmpeg && !ffmpeg) {
    std::fprintf(stderr, "bench movie: no 'ffmpeg' tool in PATH; skipping the pipe comparison\n");
  }
  // 1. Peak memory of the whole `hexgait render` process, for a short and a 10x longer movie.
  // First, while this process is small: a child's peak includes the highest memory its parent
  // had reached when it forked.
  double peak_short = 0, peak_long = 0;
  const double short_time = std::min(settings.run.duration, 100.0);
  if (!opt.no_memory) {
    std::fprintf(stderr, "bench movie: peak memory of 'hexgait render' (%g and %g time units)\n",
                 short_time, 10 * short_time);
    const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
    for (const double time : {short_time, 10 * short_time}) {
      ChildProcess child({exe, "render", "--time", std::to_string(time), "--size", opt.movie.size,
                          "--fps", std::to_string(settings.fps), "--preset", settings.preset,
                          "--crf", std::to_string(settings.crf), "--out", movie_path},
                         false);
      double peak = 0;
      if (child.Wait(&peak) != 0) throw SystemError("'hexgait render' failed in the benchmark");
      (time == short_time ? peak_short : peak_long) = peak;
    }
  }
  const auto context = GlContext::CreateOrThrow("cannot render");
  // A broken pipe must be an error from fwrite, not a silent death of the benchmark.
  std::signal(SIGPIPE, SIG_IGN);

  // The movie's frames after conversion, kept from the first repeat for the encode-only
  // reference: libx264 in process on exactly these frames, with nothing else running.
  std::vector<std::vector<uint8_t>> yuv_frames;
  const EncoderSettings encoder_settings = EncoderSettingsOf(settings);
  Measured m;
  for (int r = 0; r < opt.repeats; ++r) {
    std::fprintf(stderr, "bench movie: repeat %d/%d\n", r + 1, opt.repeats);
    {  // 2. The same simulation with no movie.
      MotorController controller(scene.model, scene.program, panel.rest_lengths, settings.run.dt);
      SimState state = MakeRestState(scene.model);
      NullObserver none;
      const auto t = Clock::now();
      Simulate(scene.model, controller, state, settings.run, none);
      m.simulate_alone.push_back(Seconds(t));
    }
    {  // 3. The in-process pipeline: render -> yuv420p -> libx264 -> MP4.
      const auto t = Clock::now();
      VideoEncoder encoder(movie_path, settings.width, settings.height, encoder_settings);
      if (r == 0) {
        encoder.set_yuv_tap([&](const uint8_t* const planes[3], const int strides[3]) {
          std::vector<uint8_t> yuv;
          yuv.reserve(static_cast<size_t>(settings.width) * settings.height * 3 / 2);
          for (int p = 0; p < 3; ++p) {
            const int rows = p == 0 ? settings.height : settings.height / 2;
            const int bytes = p == 0 ? settings.width : settings.width / 2;
            for (int y = 0; y < rows; ++y) {
              const uint8_t* row = planes[p] + static_cast<ptrdiff_t>(y) * strides[p];
              yuv.insert(yuv.end(), row, row + bytes);
            }
          }
          yuv_frames.push_back(std::move(yuv));
        });
      }
      EncoderThread encoder_thread(encoder);
      const MovieStats s = MakeMovie(scene.model, scene.program, {panel}, settings,
                                     [&](const Image& frame) { encoder_thread.Add(frame); });
      encoder_thread.Finish();
      m.movie_total.push_back(Seconds(t));
      m.simulate.push_back(s.seconds_simulate);
      m.render.push_back(s.seconds_render);
      m.compose.push_back(s.seconds_compose);
      m.convert.push_back(encoder_thread.seconds_convert());
      m.encode.push_back(encoder.seconds_encode());
      m.frames = s.frames;
      m.movie_bytes = static_cast<double>(std::filesystem::file_size(movie_path));
    }
    {  // 4. The reference: x264 alone on the same yuv420p frames.
      const int w = settings.width, h = settings.height;
      const int strides[3] = {w, w / 2, w / 2};
      const auto t = Clock::now();
      VideoEncoder encoder(reference_path, w, h, encoder_settings);
      for (const std::vector<uint8_t>& yuv : yuv_frames) {
        const uint8_t* planes[3] = {yuv.data(), yuv.data() + static_cast<size_t>(w) * h,
                                    yuv.data() + static_cast<size_t>(w) * h * 5 / 4};
        encoder.AddYuv(planes, strides);
      }
      encoder.Finish();
      m.encode_only.push_back(Seconds(t));
    }
    if (ffmpeg) {  // 5. The same frames as raw RGBA through a pipe into the ffmpeg tool.
      const auto t = Clock::now();
      // The tool encodes with the settings this benchmark reports (preset, CRF, fps...).
      ChildProcess child(
          FfmpegToolArgs(encoder_settings, settings.width, settings.height, "rgba", pipe_path),
          true);
      bool ok = true;
      MakeMovie(scene.model, scene.program, {panel}, settings, [&](const Image& frame) {
        ok = ok && std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), child.input()) ==
                       frame.rgba.size();
      });
      if (child.Wait() != 0 || !ok) throw SystemError("the ffmpeg tool failed on the raw frames");
      m.pipe_total.push_back(Seconds(t));
    }
  }

  const double frames = static_cast<double>(m.frames);
  nlohmann::json j;
  j["size"] = opt.movie.size;
  j["fps"] = settings.fps;
  j["time_units"] = settings.run.duration;
  j["frames"] = m.frames;
  j["repeats"] = opt.repeats;
  j["seconds_simulation_alone"] = Median(m.simulate_alone);
  j["seconds_movie_total"] = Median(m.movie_total);
  j["seconds_simulate_in_movie"] = Median(m.simulate);
  j["render_fps"] = frames / Median(m.render);
  j["caption_fps"] = frames / Median(m.compose);
  j["convert_fps"] = frames / Median(m.convert);
  j["encode_fps"] = frames / Median(m.encode);
  j["preset"] = settings.preset;
  j["crf"] = settings.crf;
  j["movie_megabytes"] = m.movie_bytes / 1e6;
  j["seconds_x264_encode_only"] = Median(m.encode_only);
  j["ratio_movie_to_encode_only"] = Median(m.movie_total) / Median(m.encode_only);
  j["seconds_ffmpeg_pipe_total"] = ffmpeg ? nlohmann::json(Median(m.pipe_total)) : nullptr;
  j["speedup_over_ffmpeg_pipe"] =
      ffmpeg ? nlohmann::json(Median(m.pipe_total) / Median(m.movie_total)) : nullptr;
  j["peak_mib_short_movie"] = opt.no_memory ? nlohmann::json(nullptr) : nlohmann::json(peak_short);
  j["peak_mib_long_movie"] = opt.no_memory ? nlohmann::json(nullptr) : nlohmann::json(peak_long);
  if (opt.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf(
      "movie benchmark: %s at %d fps, %g time units (%lld frames), x264 %s CRF %d, median of %d\n",
      opt.movie.size.c_str(), settings.fps, settings.run.duration, m.frames,
      settings.preset.c_str(), settings.crf, opt.repeats);
  std::printf("  simulation alone               %8.3f s\n", Median(m.simulate_alone));
  std::printf("  simulation + movie (in-process) %7.3f s\n", Median(m.movie_total));
  std::printf("    simulate                     %8.3f s\n", Median(m.simulate));
  std::printf("    render + read back           %8.3f s  %7.1f frames/s\n", Median(m.render),
              frames / Median(m.render));
  std::printf("    caption                      %8.3f s  %7.1f frames/s\n", Median(m.compose),
              frames / Median(m.compose));
  std::printf("    RGBA -> yuv420p              %8.3f s  %7.1f frames/s\n", Median(m.convert),
              frames / Median(m.convert));
  std::printf("    H.264 encode + MP4 (x264)    %8.3f s  %7.1f frames/s\n", Median(m.encode),
              frames / Median(m.encode));
  std::printf("  x264 alone on the same frames   %7.3f s  (the movie costs %.2fx this)\n",
              Median(m.encode_only), Median(m.movie_total) / Median(m.encode_only));
  std::printf("  movie file                     %7.2f MB\n", m.movie_bytes / 1e6);
  if (ffmpeg) {
    std::printf("  same frames piped to ffmpeg    %8.3f s  (in-process is %.2fx faster)\n",
                Median(m.pipe_total), Median(m.pipe_total) / Median(m.movie_total));
  }
  if (!opt.no_memory) {
    std::printf("  peak memory of 'hexgait render': %.0f MiB (%g time units), %.0f MiB (%g)\n",
                peak_short, short_time, peak_long, 10 * short_time);
  }
}

}  // namespace

void AddBenchMovie(CLI::App& bench) {
  auto opt = std::make_shared<BenchMovieOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "movie",
      "Time a movie: simulation alone vs simulation + movie, frames/s of render, colour "
      "conversion and encode, against piping raw frames into the ffmpeg tool; peak memory");
  AddGenomeOptions(cmd, opt->genome);
  AddMovieOptions(cmd, opt->movie, false);
  cmd->add_option("--repeats", opt->repeats, "Measurements per figure (the median is shown)")
      ->capture_default_str();
  cmd->add_option("--out", opt->out_dir, "Folder for the scratch movies (removed afterwards)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print the results as one JSON object");
  cmd->add_flag("--no-ffmpeg", opt->no_ffmpeg, "Skip the ffmpeg-tool comparison");
  cmd->add_flag("--no-memory", opt->no_memory, "Skip the peak-memory runs");
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
