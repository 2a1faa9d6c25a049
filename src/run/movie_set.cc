#include "run/movie_set.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/replay_request.h"
#include "run/run_state.h"
#include "run/runtime_needs.h"
#include "search/ga_optimizer.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/folder_lock.h"
#include "util/json_file.h"
#include "util/output.h"
#include "util/stop_signal.h"
#include "util/temp_registry.h"

namespace hexgait {
namespace {

// The paper's experiment (population 4, 10 generations) when no run is given; the genome is
// saved next to the movies so they can be traced and re-made.
Genome EvolveForMovie(const Scene& scene, const MovieSetSettings& opt,
                      const std::string& genome_path, const MovieSetObserver& observer) {
  EvolutionParams params;
  params.seed = opt.seed;
  params.run = MakeRunOptions(opt.scene, kPaperDuration);
  if (observer.evolving) observer.evolving(params);
  const auto start = Clock::now();
  const EvolutionResult result = Evolve(scene.model, scene.program, params, {});
  const double seconds = SecondsSince(start);
  char comment[160];
  std::snprintf(comment, sizeof comment, "best of the paper's experiment, seed %llu: distance %.6f",
                static_cast<unsigned long long>(opt.seed), result.best->fitness);
  WriteFileAtomically(genome_path, FormatGenome(result.best->genome, comment));
  if (observer.evolved) observer.evolved(seconds, result.best->fitness, genome_path);
  return result.best->genome;
}

}  // namespace

MovieSetOutcome MakeMovieSet(const MovieSetSettings& request, const MovieSetObserver& observer) {
  MovieSetSettings opt = request;
  if (!opt.run_dir.empty()) {
    // The run's own scene, read from its folder once the folder is known to be a finished run.
    IoPaths().Input("--run", opt.run_dir).Check();
    FinishedRunGenome(opt.run_dir, "--run");
    opt.scene = SceneOfFolders(opt.scene, {{"--run", opt.run_dir}});
  }
  const MovieSettings settings = MakeMovieSettings(opt.movie, opt.scene);
  // Beside the movies, a browser replay of each program, opening on the movies' view and cues.
  ReplayRequest replay_request;
  replay_request.time = opt.movie.time;
  replay_request.no_overlay = !opt.movie.overlay;
  replay_request.no_shadow = opt.movie.no_shadow;
  replay_request.view = opt.movie.view;
  // Every input is read and checked before anything is created on disk.
  IoPaths paths = SceneInputs(opt.scene);
  if (!opt.run_dir.empty()) paths.Input("--run", opt.run_dir + "/best.genome");
  for (const char* name : {"unoptimized.mp4", "evolved.mp4", "comparison.mp4", "evolved.genome",
                           "unoptimized.html", "evolved.html"}) {
    paths.Output("--out", opt.out_dir + "/" + name);
  }
  paths.Check();
  const Scene scene = LoadScene(opt.scene);
  RefuseLongMovieSettings(opt.movie, settings, scene.program.cycle_period, opt.scene.allow_long);
  // A replay holds fewer frames than a movie: past that length the replays cover its start.
  replay_request.time = std::min(replay_request.time, LongestReplay(scene, opt.scene.dt));
  const ReplaySettings replay = MakeReplaySettings(replay_request, opt.scene, scene);
  CheckRuntime(MovieNeeds(settings), "cannot render");  // before the evolution, not after it
  Genome evolved(MakeGenomeLayout(scene.model, scene.program, false));
  std::string evolved_name;
  if (!opt.run_dir.empty()) {
    const std::string path = opt.run_dir + "/best.genome";
    const std::string text = ReadTextFile(path);
    evolved = ParseGenome(
        text, path,
        MakeGenomeLayout(scene.model, scene.program, GenomeFileIsSymmetric(text, path)));
    evolved_name = "evolved (" + path + ")";
  }
  if (!std::filesystem::is_directory(opt.out_dir)) {
    std::error_code ec;
    std::filesystem::create_directories(opt.out_dir, ec);
    if (ec) throw InputError("--out '" + opt.out_dir + "': cannot create folder: " + ec.message());
  }
  // Held for the whole command: two movie sets cannot be written into one folder at once.
  const FolderLock lock(opt.out_dir, "--out");
  const std::string dir = opt.out_dir + "/";
  for (const char* name :
       {"unoptimized.mp4", "evolved.mp4", "comparison.mp4", "unoptimized.html", "evolved.html"}) {
    CheckOutputPath(dir + name, "--out");
  }
  for (const char* page : {"unoptimized.html", "evolved.html"})
    RefuseForeignPage(dir + page, "--out");
  if (opt.run_dir.empty()) {
    evolved = EvolveForMovie(scene, opt, dir + "evolved.genome", observer);
    evolved_name = "evolved (paper's GA, seed " + std::to_string(opt.seed) + ")";
  }
  const MoviePanel unoptimized_panel{
      "unoptimized program",
      PerturbedRestLengths(scene.model, scene.program,
                           Genome(MakeGenomeLayout(scene.model, scene.program, false)))};
  const MoviePanel evolved_panel{evolved_name,
                                 PerturbedRestLengths(scene.model, scene.program, evolved)};

  const auto context = GlContext::CreateOrThrow("cannot render");
  const auto start = Clock::now();
  const Genome unoptimized(MakeGenomeLayout(scene.model, scene.program, false));
  StagedFiles staged(dir);
  // Writes one movie; a diverging creature is named with the largest stable step for it.
  int index = 0;
  const auto write = [&](const std::string& name, const std::vector<MoviePanel>& panels,
                         const std::vector<const Genome*>& genomes) {
    if (observer.movie_started) observer.movie_started(index++, 3, name);
    try {
      const MovieStats stats =
          WriteMovie(staged.Stage(name), scene, panels, settings, "", observer.frame);
      if (observer.movie_written) observer.movie_written(dir + name, stats, settings);
      return stats;
    } catch (const Stopped& e) {
      throw Stopped(name + " " + e.what() + "; no movie of the set replaced");
    } catch (const MovieDiverged& e) {
      const Genome& genome = *genomes[static_cast<size_t>(e.panel())];
      throw InputError(
          panels[static_cast<size_t>(e.panel())].name + ": " +
          DivergenceMessage(e.result(), settings.run,
                            LargestStableStep(scene.model, scene.program, genome, settings.run)) +
          "; " + name + " not written, no movie of the set replaced");
    } catch (const InputError& e) {
      throw InputError(name + " not written, no movie of the set replaced: " + e.what());
    } catch (const SystemError& e) {
      throw SystemError(name + " not written, no movie of the set replaced: " + e.what());
    }
  };
  write("unoptimized.mp4", {unoptimized_panel}, {&unoptimized});
  write("evolved.mp4", {evolved_panel}, {&evolved});
  const MovieStats both =
      write("comparison.mp4", {unoptimized_panel, evolved_panel}, {&unoptimized, &evolved});
  // The runs above finished without diverging, so these cannot either.
  WriteFileAtomically(staged.Stage("unoptimized.html"),
                      ReplayHtml(scene, unoptimized, replay, unoptimized_panel.name));
  WriteFileAtomically(staged.Stage("evolved.html"),
                      ReplayHtml(scene, evolved, replay, evolved_panel.name));
  staged.CommitAll();
  const double seconds = SecondsSince(start);
  return {seconds, both.results[0], both.results[1]};
}

}  // namespace hexgait
