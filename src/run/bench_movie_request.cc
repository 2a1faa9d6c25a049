// hexgait bench movie as a request (run/bench_request.h): where a movie's time goes, against
// the ffmpeg tool fed the same frames, and the peak memory of whole `hexgait render` runs.
#include <filesystem>
#include <string>

#include "ga/genome_eval.h"
#include "run/bench_request.h"
#include "util/child_process.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {
namespace {

bool HaveFfmpegTool() {
  try {
    ChildProcess probe({"ffmpeg", "-version"}, false);
    return probe.Wait() == 0;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

MovieBenchReport MeasureMovieCost(const MovieBenchRequest& opt, const LogLine& note) {
  MovieBenchSettings bench;
  bench.movie = MakeMovieSettings(opt.movie, opt.scene);
  if (opt.repeats < 1 || opt.repeats > 100) throw InputError("--repeats must be 1 to 100");
  bench.encoder = EncoderSettingsOf(bench.movie);
  bench.size = opt.movie.size;
  bench.repeats = opt.repeats;
  // Scratch only: a folder this makes is removed at the end, and the scratch movies are
  // removed if the benchmark is stopped (a memory run's finished movie included).
  const OutputFolder out(opt.out_dir, "bench_movie.mp4");
  bench.movie_path = out.path() + "bench_movie.mp4";
  bench.pipe_path = out.path() + "bench_movie_ffmpeg.mp4";
  bench.reference_path = out.path() + "bench_movie_reference.mp4";
  const ScratchFiles scratch({bench.movie_path, bench.pipe_path, bench.reference_path});
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  const MoviePanel panel{label, PerturbedRestLengths(scene.model, scene.program, genome)};
  bench.ffmpeg = opt.ffmpeg && HaveFfmpegTool();
  if (opt.ffmpeg && !bench.ffmpeg) note("no 'ffmpeg' tool in PATH; skipping the pipe comparison");
  if (opt.memory) {
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
  return MeasureMovie(scene.model, scene.program, panel, bench, note);
}

}  // namespace hexgait
