// hexgait repertoire: MAP-Elites (or another archive optimizer, --algorithm) over the paper's
// genome, a repertoire of standing gaits binned by behaviour, with its archive, map, growth curves,
// a movie grid of chosen elites, and optionally the paper's GA run on the same budget for
// comparison (run/repertoire_run.h).
#include <cstdio>
#include <memory>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/movie_options.h"
#include "app/param_flags.h"
#include "app/view_options.h"
#include "render/gait_cues.h"
#include "run/repertoire_run.h"
#include "search/archive_optimizer.h"
#include "util/progress_bar.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

struct RepertoireOptions {
  RepertoireSettings settings;
  std::unique_ptr<ParamFlags> algorithm_flags;  // every archive optimizer's parameters
  bool quiet = false;
};

// Flags that change the archive: a resumed run takes them from archive.json instead.
// (The algorithm's own parameters are refused too, by their table.)
const char* const kRunFlags[] = {"--algorithm",  "--evaluations", "--batch",     "--seed",
                                 "--descriptor", "--bins",        "--symmetric", "--time",
                                 "--precision",  "--no-confirm",  "--dt",        "--integrator",
                                 "--out"};
// Flags that choose what is written besides the archive: a resumed run takes them from
// outputs.json unless given again.
const char* const kOutputFlags[] = {"--compare-ga", "--showcase",   "--movie-time",
                                    "--movie-size", "--movie-cues", "--no-movie"};

void Run(const RepertoireSettings& settings, bool quiet) {
  StopIsPolled();
  RepertoireObserver observer;
  ProgressBar bar("repertoire");
  size_t cells = 0;  // filled, after the last batch
  long long last_line = 0;
  if (!quiet) {
    observer.replayed = [](const ReplayCheck& check) {
      std::printf("checked the archive: %s\n", check.Text("elites").c_str());
    };
    observer.started = [&](const MapElitesState& state, const std::string& out_dir, bool resumed) {
      const MapElitesParams& p = state.params;
      std::printf(
          "repertoire: %s (%s), %lld evaluations in batches of %d, '%s' descriptor "
          "(%d axes x %d bins = %lld cells), seed %llu, %s, %d thread%s -> %s\n",
          FindArchiveOptimizerKind(p.algorithm).title, DescribeParams(p.settings).c_str(),
          p.evaluations, p.batch, p.descriptor.c_str(), state.archive.dims(), p.bins,
          state.archive.cells(), static_cast<unsigned long long>(p.seed), PrecisionText(p).c_str(),
          p.threads, p.threads == 1 ? "" : "s", out_dir.c_str());
      if (resumed) {
        std::printf("  resuming after evaluation %lld (%zu cells filled)\n", state.evaluations,
                    state.archive.filled().size());
      }
      std::fflush(stdout);
      last_line = state.evaluations;
      cells = state.archive.filled().size();
    };
    observer.progress = [&](std::string_view stage, long long done, long long total) {
      bar.Show(stage, done, total, stage == "evaluations" ? std::to_string(cells) + " cells" : "");
    };
    observer.batch = [&](const MapElitesState& s, bool done, double elapsed) {
      cells = s.archive.filled().size();
      if (!done && s.evaluations - last_line < s.params.evaluations / 10) return;
      last_line = s.evaluations;
      const ArchiveStats& a = s.history.back();
      bar.Clear();
      std::printf(
          "  %9lld evaluations  %6d cells (%5.1f%%)  QD-score %10.2f  best %7.3f  %6.0f s\n",
          a.evaluations, a.filled, 100.0 * a.filled / static_cast<double>(s.archive.cells()),
          a.qd_score, a.best, elapsed);
      if (done && s.params.confirm_in_double) {
        std::printf(
            "  %lld children float would admit were run again in double; %lld of them did not "
            "stand in double and were kept out\n",
            a.confirmed, a.refuted);
      }
      std::fflush(stdout);
    };
    observer.comparing = [&](int population) {
      bar.Clear();
      std::printf("comparison: the paper's GA, population %d, on the same budget\n", population);
      std::fflush(stdout);
    };
    observer.movie_written = [&](const std::string& path, const MovieStats& stats,
                                 const MovieSettings& movie) {
      bar.Clear();
      PrintMovieSummary(path, stats, movie);
    };
  }
  observer.saved = [&] {
    if (StopRequested()) bar.Clear();
  };
  const RepertoireOutcome outcome = RunRepertoire(settings, observer);
  bar.Clear();
  std::printf(
      "%s\nwrote %s (archive.json, archive.csv, map.png, progress.png, table.md%s) in "
      "%.0f s\n",
      outcome.tables.c_str(), outcome.dir.c_str(), outcome.movie ? ", grid.mp4" : "",
      outcome.seconds);
}

}  // namespace

void RegisterRepertoire(CLI::App& app) {
  auto opt = std::make_shared<RepertoireOptions>();
  RepertoireSettings& s = opt->settings;
  MapElitesParams& p = s.params;
  CLI::App* cmd = app.add_subcommand(
      "repertoire",
      "MAP-Elites: a repertoire of standing gaits, one per behaviour (by default each leg's "
      "duty factor), with its map, growth curves and a movie grid of chosen elites");
  cmd->add_option("--evaluations", p.evaluations, "Budget: simulations to run")
      ->capture_default_str();
  cmd->add_option("--batch", p.batch,
                  "Children made from the archive and evaluated together (the archive does not "
                  "change within a batch)")
      ->capture_default_str();
  AddSeedOption(cmd, p.seed, "Random seed");
  std::string descriptors;
  for (const BehaviourDescriptor& d : BehaviourDescriptors()) {
    descriptors += "; " + d.name + ": " + d.description;
  }
  cmd->add_option("--descriptor", p.descriptor, "Behaviour that names a gait's cell" + descriptors)
      ->capture_default_str();
  cmd->add_option("--bins", p.bins, "Bins per behaviour axis")->capture_default_str();
  std::string algorithms;
  std::vector<ParamOwner> owners;
  for (const ArchiveOptimizerKind* kind : ArchiveOptimizerKinds()) {
    algorithms += std::string("; ") + kind->name + ": " + kind->summary;
    owners.emplace_back(kind->name, kind->params);
  }
  cmd->add_option("--algorithm", p.algorithm, "What fills the archive" + algorithms)
      ->capture_default_str();
  opt->algorithm_flags = std::make_unique<ParamFlags>(cmd, owners);
  cmd->add_flag("--symmetric", p.symmetric,
                "Tie mirror-image springs: 60 genes instead of the paper's 120");
  cmd->add_option("--time", s.time, "Simulated time per evaluation: the test a gait must stand")
      ->capture_default_str();
  cmd->add_option("--precision", s.precision,
                  "auto: float, with each child float would admit run again in double and "
                  "admitted on its double result (every elite replays bit for bit in "
                  "'simulate' and the movie, at 1.3-1.4x double's rate), where the scene allows "
                  "float (--integrator euler, no slope) and not under mpirun, else double; "
                  "double; or float (also confirmed, unless --no-confirm)")
      ->check(CLI::IsMember({"auto", "double", "float"}))
      ->capture_default_str();
  cmd->add_flag("--no-confirm", s.no_confirm,
                "With --precision float: admit on float results (1.7x double's rate, but 3-9% "
                "of the elites fall when 'simulate' replays them in double)");
  cmd->add_option("--threads", p.threads, "Evaluation threads (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--batch-lanes", p.batch_lanes,
                  "Creatures simulated in lock-step per batch (0: automatic); results do not "
                  "depend on it")
      ->capture_default_str();
  cmd->add_option("--compare-ga", s.ga_population,
                  "Also run the paper's GA with this population on the same budget, and compare "
                  "(0: no comparison)")
      ->capture_default_str();
  cmd->add_option("--showcase", s.showcase,
                  "Elites in the movie grid: the farthest walker, then the most different "
                  "footfall patterns")
      ->capture_default_str();
  cmd->add_option("--movie-time", s.movie_time, "Simulated time of the movie grid")
      ->capture_default_str();
  cmd->add_option("--movie-size", s.movie_size, "Frame size of the movie grid, WIDTHxHEIGHT")
      ->capture_default_str();
  cmd->add_option("--movie-cues", s.movie_cues,
                  std::string("Gait cues in the movie grid: ") + kCueNames + ", all or none")
      ->capture_default_str();
  cmd->add_flag("--no-movie", s.no_movie, "Do not render the movie grid");
  AddGlOption(cmd);
  cmd->add_option("--checkpoint-seconds", s.checkpoint_seconds,
                  "Save archive.json at most this often (and after the last batch, and on Ctrl-C)")
      ->capture_default_str();
  cmd->add_option("--out", s.out_dir, "Folder for the archive, figures and movie")
      ->capture_default_str();
  cmd->add_option(
      "--resume", s.resume_dir,
      "Continue the interrupted run in this folder from its archive.json, writing what it "
      "was started for (its outputs.json) unless an output flag is given again");
  cmd->add_flag("--quiet", opt->quiet, "No progress, only the tables and where they went");
  AddSceneOptions(cmd, s.scene);
  Distributed(cmd);
  cmd->callback([opt, cmd] {
    RepertoireSettings settings = opt->settings;
    settings.params.settings = opt->algorithm_flags->Given();
    for (const char* flag : kRunFlags) {
      if (cmd->count(flag) > 0) settings.run_flags_given.push_back(flag);
    }
    for (const char* flag : kOutputFlags) {
      if (cmd->count(flag) > 0) settings.output_flags_given.push_back(flag);
    }
    for (const std::string& flag : opt->algorithm_flags->flags()) {
      if (cmd->count(flag) > 0) settings.run_flags_given.push_back(flag);
    }
    Run(settings, opt->quiet);
  });
}

}  // namespace hexgait
