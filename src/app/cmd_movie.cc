// hexgait movie: the movies a report needs, from one evolve run: the unoptimised program, the
// evolved one, and both stacked on one clock (comparison.mp4), each captioned (run/movie_set.h).
#include <cstdio>
#include <memory>
#include <optional>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/movie_options.h"
#include "run/movie_set.h"
#include "util/progress_bar.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

void Run(const MovieSetSettings& settings) {
  StopIsPolled();  // stops between frames, removing the unfinished movie
  MovieSetObserver observer;
  observer.evolving = [](const EvolutionParams& params) {
    std::printf(
        "no --run given: evolving with the paper's settings (population %d, %d "
        "generations, seed %llu)\n",
        params.population, params.generations, static_cast<unsigned long long>(params.seed));
    std::fflush(stdout);
  };
  observer.evolved = [](double seconds, double distance, const std::string& genome_path) {
    std::printf("evolved in %.1f s: distance %.4f; genome saved to %s\n", seconds, distance,
                genome_path.c_str());
  };
  std::optional<ProgressBar> bar;  // the movie being written
  observer.movie_started = [&bar](int index, int count, const std::string& name) {
    bar.emplace("rendering " + name);
    std::printf("[%d/%d] ", index + 1, count);
    std::fflush(stdout);
  };
  observer.frame = [&bar](std::string_view stage, long long frame, long long total) {
    bar->Show(stage, frame, total);
  };
  observer.movie_written = [&bar](const std::string& path, const MovieStats& stats,
                                  const MovieSettings& movie) {
    bar.reset();
    PrintMovieSummary(path, stats, movie);
  };
  const MovieSetOutcome outcome = MakeMovieSet(settings, observer);
  std::printf("replays: %s/unoptimized.html and %s/evolved.html (open in a web browser)\n",
              settings.out_dir.c_str(), settings.out_dir.c_str());
  std::printf("movies done in %.1f s: unoptimized distance %.2f%s, evolved distance %.2f%s\n",
              outcome.seconds, outcome.unoptimized.distance,
              outcome.unoptimized.fell ? " (fell)" : "", outcome.evolved.distance,
              outcome.evolved.fell ? " (fell)" : "");
}

}  // namespace

void RegisterMovie(CLI::App& app) {
  auto opt = std::make_shared<MovieSetSettings>();
  CLI::App* cmd = app.add_subcommand(
      "movie",
      "Render the movies a report needs: unoptimized.mp4, evolved.mp4 and comparison.mp4 (both "
      "on one clock), and a browser replay of each program (unoptimized.html, evolved.html)");
  cmd->add_option("--run", opt->run_dir,
                  "Folder of a 'hexgait evolve' run (its best.genome); without it, the paper's "
                  "experiment is evolved first");
  AddSeedOption(cmd, opt->seed, "Seed of that evolution when no --run is given");
  cmd->add_option("--out", opt->out_dir, "Folder for the movies")->capture_default_str();
  AddMovieOptions(cmd, opt->movie, false);
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
