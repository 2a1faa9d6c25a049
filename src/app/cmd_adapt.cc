// hexgait adapt: a damaged creature recovers a gait from a repertoire in a few trials
// (Intelligent Trial and Error, src/run/adapt_run.h).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/view_options.h"
#include "model/damage.h"
#include "run/adapt_run.h"
#include "run/evolve_run.h"
#include "util/progress_bar.h"

namespace hexgait {

namespace {

void Run(AdaptFile opt) {
  ProgressBar bar("adapting");
  opt.request.on_progress = bar.Hook();
  const AdaptOutcome o = AdaptToFolder(opt);
  bar.Clear();
  std::printf("checked the archive: %s\n", o.prior_check.Text("elites").c_str());
  for (size_t i = 0; i < o.adaptation.trials.size(); ++i) {
    const Trial& t = o.adaptation.trials[i];
    const std::string prior = o.library.empty() ? "" : ", prior " + o.PriorName(t.prior);
    std::printf(
        "trial %2zu: elite %4d (cell %d) predicted %6.2f +- %5.2f%s, walked %6.2f%s, best "
        "%6.2f\n",
        i + 1, t.elite, o.cells[static_cast<size_t>(t.elite)], t.predicted_mean, t.predicted_std,
        prior.c_str(), t.distance, o.trial_runs[i].diverged ? " (diverged)" : "", t.best);
  }
  const double best = o.adaptation.trials.back().best;
  const double all = o.damaged[static_cast<size_t>(o.damaged_best)].distance;
  const auto count = [](int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  // The adapted gait's fall is said with its distance: a distance alone reads as a walk.
  const RunResult& adapted = o.damaged[static_cast<size_t>(o.adapted)];
  const std::string falls = adapted.fell ? " but " + FallText(adapted) : "";
  // Rounded first, and + 0.0 turns a negative zero into "0%", never "-0%".
  const double percent = std::round(all > 0 ? 100 * best / all : 0.0) + 0.0;
  std::printf(
      "%s after %s: adapted gait walks %.2f%s on %s; the intact best gait %.2f; the best of "
      "all %zu elites %.2f (%.0f%%); the best of %s %.2f; the GA from the intact best "
      "%.2f in %d evaluations\n",
      TrialStopText(o.adaptation.stop).c_str(), count(o.trials(), "trial", "trials").c_str(), best,
      falls.c_str(), o.damage.c_str(), o.damaged[static_cast<size_t>(o.intact_best)].distance,
      o.cells.size(), all, percent, count(o.trials(), "random elite", "random elites").c_str(),
      o.random_best, o.ga_best, o.ga_evaluations);
  if (!o.library.empty()) {
    std::printf("the library of %zu damages: %lld of its %zu elite runs made\n", o.library.size(),
                o.library_runs, o.library.size() * o.cells.size());
  }
  if (o.diverged() > 0) {
    std::printf(
        "%d of the %zu elites diverged on the damaged creature (distance 0; neither fell "
        "nor stood)\n",
        o.diverged(), o.cells.size());
  }
  std::printf("wrote %s: trials.csv, elites.csv, adapt.json, adapted.genome, adapt.png%s\n",
              opt.out.c_str(), opt.no_movie ? "" : ", adapt.mp4");
}

}  // namespace

void RegisterAdapt(CLI::App& app) {
  auto opt = std::make_shared<AdaptFile>();
  // A short movie: the damage shows within a few cycles.
  opt->movie.time = 400;
  opt->movie.view.cues = "footprints,swing";
  CLI::App* cmd = app.add_subcommand(
      "adapt",
      "Recover a gait for a damaged creature from a repertoire in a few trials (Intelligent "
      "Trial and Error: a Gaussian process over the elites, next trial by upper confidence "
      "bound)");
  AdaptRequest& r = opt->request;
  TrialAndErrorParams& p = r.params;
  cmd->add_option("--repertoire", r.repertoire_dir, "A finished 'hexgait repertoire' folder")
      ->required();
  cmd->add_option("--damage", r.damage, std::string("The damage: ") + kDamageHelp)->required();
  cmd->add_option("--trials", p.max_trials, "Most trials")->capture_default_str();
  cmd->add_flag(
      "--no-stop", [&p](int64_t) { p.stop_rule = false; },
      "Run every one of --trials trials, with no stop rule (a comparison at a fixed number)");
  cmd->add_option("--stop", p.stop_fraction,
                  "Stop once the best trial reaches this fraction of the best prediction")
      ->capture_default_str();
  cmd->add_option_function<std::string>(
      "--normalise", [&p](const std::string& name) { p.normalise = ParseNormalisation(name); },
      "How distances meet the Gaussian process: none (as they are), best (divided by the "
      "archive's best) or spread (signal variance set to the archive's variance); default " +
          NormalisationName(p.normalise));
  cmd->add_option("--kappa", p.kappa, "Upper confidence bound: mean + kappa x standard deviation")
      ->capture_default_str();
  cmd->add_option("--length-scale", p.gp.length_scale,
                  "Matern 5/2 length scale, in descriptor units")
      ->capture_default_str();
  std::string library_kinds;
  for (const std::string& kind : DefaultDamageLibraryKinds()) {
    library_kinds += (library_kinds.empty() ? "" : ", ") + kind;
  }
  cmd->add_flag(
      "--library", [&r](int64_t) { r.library_kinds = DefaultDamageLibraryKinds(); },
      "Take as the prior, after every trial, the damage of a library of simulated damages "
      "(every leg with " +
          library_kinds +
          "; the damage itself left out) whose gaits look most like the trials', running the "
          "elites on the library's creatures as the choice needs them");
  cmd->add_option("--seed", r.seed, "Seed of the random-elites comparison")->capture_default_str();
  cmd->add_option("--threads", r.threads, "Threads for running every elite (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--creature", r.creature_path,
                  "The repertoire's creature file (default: its recorded built-in creature)");
  cmd->add_option("--motor", r.motor_path, "The repertoire's motor program file");
  cmd->add_flag("--no-movie", opt->no_movie, "Do not render adapt.mp4");
  AddGlOption(cmd);
  cmd->add_option("--movie-time", opt->movie.time, "Simulated time the movie shows")
      ->capture_default_str();
  cmd->add_option("--movie-size", opt->movie.size, "Movie size, WIDTHxHEIGHT")
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "Folder to write (replaced whole)")->capture_default_str();
  cmd->add_option("--movie-cues", opt->movie.view.cues, "Gait cues in the movie")
      ->capture_default_str();
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
