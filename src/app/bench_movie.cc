#include "app/bench_movie.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/bench_common.h"
#include "app/cli_common.h"
#include "app/movie_options.h"
#include "bench/movie_bench.h"
#include "ga/genome_eval.h"
#include "util/child_process.h"
#include "util/error.h"
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

bool HaveFfmpegTool() {
  try {
    ChildProcess probe({"ffmpeg", "-version"}, false);
    return probe.Wait() == 0;
  } catch (const InputError&) {
    return false;
  }
}

void PrintTable(const MovieBenchReport& r) {
  const double frames = static_cast<double>(r.frames);
  std::printf(
      "movie benchmark: %s at %d fps, %g time units (%lld frames), x264 %s CRF %d, median of %d\n",
      r.size.c_str(), r.fps, r.time_units, r.frames, r.preset.c_str(), r.crf, r.repeats);
  std::printf("  simulation alone               %8.3f s\n", r.simulation_alone);
  std::printf("  simulation + movie (in-process) %7.3f s\n", r.movie_total);
  std::printf("    simulate                     %8.3f s\n", r.simulate);
  std::printf("    render + read back           %8.3f s  %7.1f frames/s\n", r.render,
              frames / r.render);
  std::printf("    caption                      %8.3f s  %7.1f frames/s\n", r.compose,
              frames / r.compose);
  std::printf("    RGBA -> yuv420p              %8.3f s  %7.1f frames/s\n", r.convert,
              frames / r.convert);
  std::printf("    H.264 encode + MP4 (x264)    %8.3f s  %7.1f frames/s\n", r.encode,
              frames / r.encode);
  std::printf("  x264 alone on the same frames   %7.3f s  (the movie costs %.2fx this)\n",
              r.encode_only, r.movie_total / r.encode_only);
  std::printf("  movie file                     %7.2f MB\n", r.movie_bytes / 1e6);
  if (r.ffmpeg) {
    std::printf("  same frames piped to ffmpeg    %8.3f s  (in-process is %.2fx faster)\n",
                r.ffmpeg_pipe_total, r.ffmpeg_pipe_total / r.movie_total);
  }
  if (r.memory) {
    std::printf("  peak memory of 'hexgait render': %.0f MiB (%g time units), %.0f MiB (%g)\n",
                r.peak_mib_short, r.short_time, r.peak_mib_long, 10 * r.short_time);
  }
}

void Run(const BenchMovieOptions& opt) {
  MovieBenchSettings bench;
  bench.movie = MakeMovieSettings(opt.movie, opt.scene);
  if (opt.repeats < 1 || opt.repeats > 100) throw InputError("--repeats must be 1 to 100");
  bench.encoder = EncoderSettingsOf(bench.movie);
  bench.size = opt.movie.size;
  bench.repeats = opt.repeats;
  // Scratch only: a folder this makes is removed at the end, and the scratch movies are
  // removed if the benchmark is stopped (a memory run's finished movie included).
  const BenchOutDir out(opt.out_dir, "bench_movie.mp4");
  bench.movie_path = out.path() + "bench_movie.mp4";
  bench.pipe_path = out.path() + "bench_movie_ffmpeg.mp4";
  bench.reference_path = out.path() + "bench_movie_reference.mp4";
  const ScratchFiles scratch({bench.movie_path, bench.pipe_path, bench.reference_path});
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  const MoviePanel panel{label, PerturbedRestLengths(scene.model, scene.program, genome)};
  bench.ffmpeg = !opt.no_ffmpeg && HaveFfmpegTool();
  if (!opt.no_ffmpeg && !bench.ffmpeg) {
    std::fprintf(stderr, "bench movie: no 'ffmpeg' tool in PATH; skipping the pipe comparison\n");
  }
  if (!opt.no_memory) {
    // A whole `hexgait render` of the same movie, as a child process.
    bench.peak_memory_of_render = [&opt, &bench](double time) {
      const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
      const MovieSettings& s = bench.movie;
      ChildProcess child({exe, "render", "--time", std::to_string(time), "--size", opt.movie.size,
                          "--fps", std::to_string(s.fps), "--preset", s.preset, "--crf",
                          std::to_string(s.crf), "--out", bench.movie_path},
                         false);
      double peak = 0;
      if (child.Wait(&peak) != 0) throw SystemError("'hexgait render' failed in the benchmark");
      return peak;
    };
  }
  const MovieBenchReport report = MeasureMovie(
      scene.model, scene.program, panel, bench,
      [](const std::string& line) { std::fprintf(stderr, "bench movie: %s\n", line.c_str()); });
  if (opt.json) {
    std::printf("%s\n", MovieBenchReportJson(report).dump(2).c_str());
  } else {
    PrintTable(report);
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
