#include "app/bench_movie.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_common.h"
#include "app/movie_options.h"
#include "run/bench_request.h"

namespace hexgait {
namespace {

struct BenchMovieFlags {
  MovieBenchRequest request;
  bool json = false;
  bool no_ffmpeg = false;
  bool no_memory = false;
};

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

void Run(const MovieBenchRequest& request, bool json) {
  const MovieBenchReport report = MeasureMovieCost(request, [](const std::string& line) {
    std::fprintf(stderr, "bench movie: %s\n", line.c_str());
  });
  if (json) {
    std::printf("%s\n", MovieBenchReportJson(report).dump(2).c_str());
  } else {
    PrintTable(report);
  }
}

}  // namespace

void AddBenchMovie(CLI::App& bench) {
  auto opt = std::make_shared<BenchMovieFlags>();
  CLI::App* cmd = bench.add_subcommand(
      "movie",
      "Time a movie: simulation alone vs simulation + movie, frames/s of render, colour "
      "conversion and encode, against piping raw frames into the ffmpeg tool; peak memory");
  AddGenomeOptions(cmd, opt->request.genome);
  AddMovieOptions(cmd, opt->request.movie, false);
  cmd->add_option("--repeats", opt->request.repeats,
                  "Measurements per figure (the median is shown)")
      ->capture_default_str();
  cmd->add_option("--out", opt->request.out_dir,
                  "Folder for the scratch movies (removed afterwards)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print the results as one JSON object");
  cmd->add_flag("--no-ffmpeg", opt->no_ffmpeg, "Skip the ffmpeg-tool comparison");
  cmd->add_flag("--no-memory", opt->no_memory, "Skip the peak-memory runs");
  AddSceneOptions(cmd, opt->request.scene);
  cmd->callback([opt] {
    opt->request.ffmpeg = !opt->no_ffmpeg;
    opt->request.memory = !opt->no_memory;
    Run(opt->request, opt->json);
  });
}

}  // namespace hexgait
