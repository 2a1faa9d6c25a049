#include "run/adapt_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "eval/evaluator.h"
#include "ga/behaviour.h"
#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "ga/map_elites_checkpoint.h"
#include "ga/rng.h"
#include "model/damage.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "render/gl_context.h"
#include "report/adapt_report.h"
#include "report/csv.h"
#include "report/number_text.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/repertoire_run.h"
#include "run/run_folder.h"
#include "run/run_state.h"
#include "run/runtime_needs.h"
#include "search/ga_optimizer.h"
#include "search/stored_results.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output.h"
#include "util/parallel_for.h"

namespace hexgait {
namespace {

// The best of `count` elites drawn without replacement (a partial Fisher-Yates shuffle).
double BestOfRandom(const std::vector<RunResult>& results, int count, uint64_t seed) {
  std::vector<int> order(results.size());
  std::iota(order.begin(), order.end(), 0);
  Rng rng = Rng::ForStream(seed, 0);
  double best = -1e300;
  const int n = std::min<int>(count, static_cast<int>(order.size()));
  for (int i = 0; i < n; ++i) {
    const int j = i + static_cast<int>(rng.NextBelow(static_cast<uint64_t>(order.size() - i)));
    std::swap(order[i], order[j]);
    best = std::max(best, results[order[i]].distance);
  }
  return best;
}

int BestOf(const std::vector<double>& values) {
  return static_cast<int>(std::max_element(values.begin(), values.end()) - values.begin());
}

// The prior is the archive's distances: its elites replayed on the intact creature, not
// trusted (the checksum guards against damage, not an edit), with the evaluator that admitted
// them (double when the repertoire confirmed its admissions in double).
ReplayCheck ReplayPrior(const Scene& intact, const MapElitesState& state,
                        const std::string& archive_path, int threads, const Progress& between) {
  EvaluatorConfig config = EvaluatorConfigOf(state.params);
  config.threads = threads;
  if (state.params.confirm_in_double) config.precision = Precision::kDouble;
  const auto evaluator = MakeLocalEvaluator(intact.model, intact.program, config);
  return ReplayStoredResults(StoredElites(state.archive, intact.model, intact.program), *evaluator,
                             archive_path, kDefaultMaxReplays, threads, between);
}

// One run of `genome` on `scene`, as the evaluator runs it (the same bits as its run among a
// population's), advanced 65,536 steps (a few milliseconds) at a time with `between(done, total)`
// called between them.
RunResult RunOne(const Scene& scene, const RunOptions& run, const Genome& genome,
                 const std::function<void(long long, long long)>& between) {
  MotorController controller(scene.model, scene.program,
                             PerturbedRestLengths(scene.model, scene.program, genome), run.dt);
  SimState creature = MakeRestState(scene.model);
  NullObserver none;
  return SimulateInChunks(scene.model, controller, creature, run, none, 1 << 16, between);
}

TrialMeasure MeasureOf(const Scene& scene, const BehaviourDescriptor& descriptor, int dims,
                       const RunResult& result) {
  const std::vector<double> shown = BehaviourOf(scene.model, descriptor, result);
  return TrialMeasure(result.distance, Eigen::Map<const Eigen::VectorXd>(shown.data(), dims));
}

}  // namespace

std::string AdaptOutcome::PriorName(int member) const {
  return member < 0 ? kIntactPriorName : library[static_cast<size_t>(member)];
}

int AdaptOutcome::diverged() const {
  return static_cast<int>(
      std::count_if(damaged.begin(), damaged.end(), [](const RunResult& r) { return r.diverged; }));
}

AdaptOutcome AdaptToDamage(const AdaptRequest& request) {
  const auto start = Clock::now();
  if (request.damage.empty()) {
    throw InputError("--damage is required: the damage to adapt to, e.g. right_front:weak=0.2");
  }
  // The options' own names first (Python's keywords match them), then the library's checks.
  const TrialAndErrorParams& p = request.params;
  if (p.max_trials < 1 || p.max_trials > 10000) throw InputError("--trials must be in [1, 10000]");
  if (!(p.stop_fraction > 0 && p.stop_fraction <= 1)) throw InputError("--stop must be in (0, 1]");
  if (!(p.kappa >= 0 && p.kappa <= 1e3)) throw InputError("--kappa must be in [0, 1000]");
  if (!(p.gp.length_scale > 0 && p.gp.length_scale <= 100)) {
    throw InputError("--length-scale must be in (0, 100]");
  }
  ValidateTrialAndErrorParams(request.params);
  const std::string dir = request.repertoire_dir;
  // The intact scene the repertoire was made on (its record's), then the same scene damaged.
  SceneOptions flags;
  flags.creature_path = request.creature_path;
  flags.motor_path = request.motor_path;
  if (!flags.creature_path.empty()) flags.given.insert("--creature");
  if (!flags.motor_path.empty()) flags.given.insert("--motor");
  LoadedRepertoire repertoire = LoadRepertoire(dir, flags, "--repertoire");
  const SceneOptions& intact = repertoire.options;
  if (!intact.damage.empty()) {
    throw InputError("--repertoire '" + dir +
                     "': made on a damaged creature; adaptation starts from an intact one");
  }
  MapElitesState& state = repertoire.state;
  const Scene& intact_scene = repertoire.scene;
  const std::string archive_path = dir + "/" + kArchiveFile;
  SceneOptions damaged_options = intact;  // the record's step and integrator
  damaged_options.damage = request.damage;
  damaged_options.expected_fingerprint.clear();  // the damage changes what it covers
  const Scene scene = LoadScene(damaged_options);
  // The library's creatures, each checked now: a bad entry is found before any simulation.
  std::vector<Scene> library_scenes;
  for (const std::string& damage : DamageLibrary(intact_scene.model, request.library_kinds)) {
    SceneOptions options = damaged_options;
    options.damage = damage;
    Scene member = LoadScene(options);
    if (member.model.damage != scene.model.damage) library_scenes.push_back(std::move(member));
  }
  // The figure and the movie come last, after every trial: what they need is found now.
  RuntimeNeeds needs;
  needs.figures = request.figure;
  if (request.movie) needs |= MovieNeeds(MakeMovieSettings(*request.movie, damaged_options));
  CheckRuntime(needs, "cannot render adapt.mp4");
  // Each part reported under its own stage; the library's hooks name what they count, the
  // stage here says which elites.
  const auto progress = [&](std::string_view stage, long long done, long long total) {
    if (request.on_progress) request.on_progress(stage, done, total);
  };
  const auto as = [&](std::string_view stage) {
    return [&progress, stage](std::string_view, long long done, long long total) {
      progress(stage, done, total);
    };
  };

  AdaptOutcome out;
  out.scene = scene;
  out.scene_options = damaged_options;
  out.repertoire_scene = intact;
  out.damage = scene.model.damage;
  const RunOptions& run = state.params.run;
  out.time = run.duration;
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(state.params.descriptor);
  out.descriptor_dims = state.archive.dims();
  std::vector<ArchiveElite> elites;
  for (int cell = 0; cell < state.archive.cells(); ++cell) {
    const std::optional<Elite>& elite = state.archive.at(cell);
    if (!elite) continue;
    std::vector<double> d(static_cast<size_t>(out.descriptor_dims));
    descriptor.measure(intact_scene.model, elite->result, d.data());
    out.cells.push_back(cell);
    out.descriptor.push_back(d);
    out.prior.push_back(elite->fitness);
    out.genomes.push_back(elite->genome);
    elites.push_back(
        {Eigen::Map<const Eigen::VectorXd>(d.data(), static_cast<Eigen::Index>(d.size())),
         elite->fitness});
  }
  if (elites.empty()) throw InputError("--repertoire '" + dir + "': the archive is empty");

  out.prior_check = ReplayPrior(intact_scene, state, archive_path, request.threads,
                                as("elites replayed on the intact creature"));

  // Every elite once on the damaged creature, in double: for the figure and the comparisons.
  EvaluatorConfig config;
  config.run = run;
  config.threads = request.threads;
  const auto evaluator = MakeLocalEvaluator(scene.model, scene.program, config);
  std::vector<const Genome*> pointers;
  for (const Genome& g : out.genomes) pointers.push_back(&g);
  const std::vector<RestLengthTable> tables =
      PerturbedRestLengths(scene.model, scene.program, pointers);
  out.damaged = EvaluateInSlices(*evaluator, tables, request.threads, 0.25,
                                 as("elites run on the damaged creature"));
  std::vector<double> damaged_distance;
  for (const RunResult& r : out.damaged) damaged_distance.push_back(r.distance);
  out.intact_best = BestOf(out.prior);
  out.damaged_best = BestOf(damaged_distance);
  if (std::all_of(out.damaged.begin(), out.damaged.end(),
                  [](const RunResult& r) { return r.fell || r.diverged; })) {
    char best[32];
    std::snprintf(best, sizeof best, "%.3f", damaged_distance[out.damaged_best]);
    const int diverged = out.diverged();
    throw InputError(
        "--damage '" + out.damage + "': every one of the repertoire's " +
        std::to_string(elites.size()) + " elites falls" +
        (diverged > 0 ? " or diverges (" + std::to_string(diverged) + " diverge)" : std::string()) +
        " on the damaged creature (the farthest gets " + best +
        " before falling): there is no gait to adapt to");
  }

  // The library: its runs made when the loop first reads them (adapt/library_runs.h), each run
  // as the damaged runs above. A member asked for more elites than there are threads (every
  // elite, once the loop takes it as its prior) runs through its evaluator, in lanes on every
  // thread; the runs at the tried elites, a few per member, run side by side one simulation each,
  // as many at once as there are threads, with the caller told between those rounds.
  const int threads = ResolveThreadCount(request.threads);
  const RunLibrary run_library = [&](const std::vector<LibraryRun>& asked) {
    std::vector<TrialMeasure> measured(asked.size(), TrialMeasure(0));
    std::vector<std::vector<size_t>> by_member(library_scenes.size());
    for (size_t i = 0; i < asked.size(); ++i) {
      by_member[static_cast<size_t>(asked[i].member)].push_back(i);
    }
    std::vector<size_t> singles;
    for (size_t m = 0; m < by_member.size(); ++m) {
      const std::vector<size_t>& runs = by_member[m];
      if (static_cast<int>(runs.size()) <= threads) {
        singles.insert(singles.end(), runs.begin(), runs.end());
        continue;
      }
      const Scene& member = library_scenes[m];
      std::vector<const Genome*> genomes;
      for (const size_t i : runs) genomes.push_back(pointers[static_cast<size_t>(asked[i].elite)]);
      const auto member_evaluator = MakeLocalEvaluator(member.model, member.program, config);
      const std::vector<RunResult> results = EvaluateInSlices(
          *member_evaluator, PerturbedRestLengths(member.model, member.program, genomes),
          request.threads, 0.25, as("elites run on a library damage"));
      for (size_t k = 0; k < runs.size(); ++k) {
        measured[runs[k]] = MeasureOf(member, descriptor, out.descriptor_dims, results[k]);
      }
    }
    for (size_t first = 0; first < singles.size(); first += static_cast<size_t>(threads)) {
      progress("library runs at the tried elites", static_cast<long long>(first),
               static_cast<long long>(singles.size()));
      const size_t count = std::min(singles.size() - first, static_cast<size_t>(threads));
      ParallelFor(count, threads, [&](size_t k) {
        const LibraryRun& r = asked[singles[first + k]];
        const Scene& member = library_scenes[static_cast<size_t>(r.member)];
        measured[singles[first + k]] =
            MeasureOf(member, descriptor, out.descriptor_dims,
                      RunOne(member, run, out.genomes[static_cast<size_t>(r.elite)],
                             [](long long, long long) {}));
      });
    }
    return measured;
  };
  std::vector<std::string> library_names;
  for (const Scene& member : library_scenes) library_names.push_back(member.model.damage);
  out.library = library_names;
  LibraryRuns library(std::move(library_names), static_cast<int>(elites.size()),
                      out.descriptor_dims, run_library);

  // The trials: each one simulation of the chosen elite on the damaged creature, with the caller
  // told between its chunks, so a repertoire of long runs does not hold a Ctrl-C from Python for
  // a whole trial. The same bits as that elite's run among every elite's above.
  const RunTrial trial = [&](int index) {
    const int number = static_cast<int>(out.trial_runs.size());
    const auto between = [&](long long, long long) {
      progress("trials", number, request.params.max_trials);
    };
    between(0, 0);
    out.trial_runs.push_back(RunOne(scene, run, out.genomes[static_cast<size_t>(index)], between));
    return MeasureOf(scene, descriptor, out.descriptor_dims, out.trial_runs.back());
  };
  out.adaptation = RunTrialAndError(elites, trial, request.params, library);
  out.library_runs = library.runs_made();
  out.adapted = out.adaptation.trials.back().best_elite;
  // The comparisons at `trials` trials: the best of as many random elites, and the GA from the
  // intact best, whose generation 0 is the intact best and 3 mutants of it, each later
  // generation 3 new children beside the elite; as few generations as reach the trials' count
  // (one at least, the GA's minimum).
  const auto at_trials = [&](int trials) {
    AdaptOutcome::AtTrials at;
    at.trials = trials;
    at.adapted = out.adaptation.trials[static_cast<size_t>(trials - 1)].best;
    at.random_best = BestOfRandom(out.damaged, trials, request.seed);
    EvolutionParams ga;
    ga.seed = request.seed;
    ga.run = run;
    ga.threads = request.threads;
    ga.symmetric = out.genomes[static_cast<size_t>(out.intact_best)].layout().symmetric;
    ga.start = out.genomes[static_cast<size_t>(out.intact_best)].genes();
    ga.generations =
        std::max(1, (trials - ga.population + 2) / (ga.population - ga.settings.Integer("elites")));
    EvolutionCallbacks callbacks;
    callbacks.on_generation = [&](const GenerationStats& stats, const std::vector<Individual>&) {
      progress("GA comparison generations", stats.generation + 1, ga.generations + 1);
    };
    const EvolutionResult evolved = Evolve(scene.model, scene.program, ga, callbacks);
    at.ga_best = evolved.best->fitness;
    at.ga_evaluations = evolved.total_evaluations;
    return at;
  };
  const AdaptOutcome::AtTrials all = at_trials(out.trials());
  out.random_best = all.random_best;
  out.ga_best = all.ga_best;
  out.ga_evaluations = all.ga_evaluations;
  const int rule = out.adaptation.stop_rule_trials;
  if (!request.params.stop_rule && rule > 0) {
    out.at_stop_rule = rule == out.trials() ? all : at_trials(rule);
  }
  out.seconds = SecondsSince(start);
  return out;
}

std::unique_ptr<AtomicDir> TakeAdaptFolder(const std::string& out_dir) {
  return std::make_unique<AtomicDir>(out_dir, ".hexgait-adapt", "--out");
}

void WriteAdaptFolder(const AdaptRequest& request, const AdaptOutcome& o, AtomicDir& dir) {
  std::ostringstream trials;
  trials << "trial,elite,cell,predicted_mean,predicted_std,distance,best,best_elite,fell,"
            "diverged,prior\n";
  for (size_t i = 0; i < o.adaptation.trials.size(); ++i) {
    const Trial& t = o.adaptation.trials[i];
    const RunResult& r = o.trial_runs[i];
    trials << i + 1 << ',' << t.elite << ',' << o.cells[static_cast<size_t>(t.elite)] << ','
           << Exact(t.predicted_mean) << ',' << Exact(t.predicted_std) << ',' << Exact(t.distance)
           << ',' << Exact(t.best) << ',' << t.best_elite << ',' << (r.fell ? 1 : 0) << ','
           << (r.diverged ? 1 : 0) << ',' << CsvText(o.PriorName(t.prior)) << '\n';
  }
  WriteFileAtomically(dir.File("trials.csv"), trials.str());
  std::ostringstream elites;
  elites << "elite,cell";
  for (int k = 0; k < o.descriptor_dims; ++k) elites << ",descriptor_" << k;
  elites << ",intact_distance,damaged_distance,damaged_fell,damaged_diverged\n";
  for (size_t e = 0; e < o.cells.size(); ++e) {
    elites << e << ',' << o.cells[e];
    for (double d : o.descriptor[e]) elites << ',' << Exact(d);
    elites << ',' << Exact(o.prior[e]) << ',' << Exact(o.damaged[e].distance) << ','
           << (o.damaged[e].fell ? 1 : 0) << ',' << (o.damaged[e].diverged ? 1 : 0) << '\n';
  }
  WriteFileAtomically(dir.File("elites.csv"), elites.str());
  WriteFileAtomically(
      dir.File("adapted.genome"),
      FormatGenome(o.genomes[static_cast<size_t>(o.adapted)],
                   "adapted to " + o.damage + " (elite " + std::to_string(o.adapted) + " of " +
                       request.repertoire_dir + ")"));
  const auto distance_of = [&](int elite) {
    return o.damaged[static_cast<size_t>(elite)].distance;
  };
  nlohmann::ordered_json j;
  j["hexgait_version"] = HEXGAIT_VERSION;
  j["repertoire"] = request.repertoire_dir;
  // The repertoire's intact scene: a reader of this folder alone (report --adapt) can tell
  // which scene it belongs to (run/folder_scene.h).
  const SceneOptions& intact = o.repertoire_scene;
  j["scene"] = {{"creature", intact.creature_path},
                {"motor", intact.motor_path},
                {"dt", intact.dt},
                {"integrator", intact.integrator},
                {"scene_fingerprint", intact.expected_fingerprint}};
  j["damage"] = o.damage;
  j["time"] = o.time;
  j["elites"] = o.cells.size();
  j["elites_diverged_on_damaged"] = o.diverged();
  j["elites_replayed_intact"] = o.prior_check.replayed;
  j["params"] = {{"length_scale", request.params.gp.length_scale},
                 {"signal_variance", request.params.gp.signal_variance},
                 {"noise", request.params.gp.noise},
                 {"normalise", NormalisationName(request.params.normalise)},
                 {"kappa", request.params.kappa},
                 {"stop_fraction", request.params.stop_fraction},
                 {"stop_rule", request.params.stop_rule},
                 {"max_trials", request.params.max_trials},
                 {"seed", std::to_string(request.seed)}};
  j["library"] = o.library;
  j["library_runs"] = {{"made", o.library_runs},
                       {"of", static_cast<long long>(o.library.size() * o.cells.size())}};
  j["trials"] = o.trials();
  j["stopped"] = TrialStopText(o.adaptation.stop);
  j["adapted"] = {{"elite", o.adapted}, {"distance", o.adaptation.trials.back().best}};
  j["intact_best"] = {{"elite", o.intact_best},
                      {"intact_distance", o.prior[static_cast<size_t>(o.intact_best)]},
                      {"damaged_distance", distance_of(o.intact_best)},
                      {"damaged_fell", o.damaged[static_cast<size_t>(o.intact_best)].fell},
                      {"damaged_diverged", o.damaged[static_cast<size_t>(o.intact_best)].diverged}};
  j["best_elite_on_damaged"] = {{"elite", o.damaged_best},
                                {"distance", distance_of(o.damaged_best)}};
  j["random_elites"] = {{"count", o.trials()}, {"best", o.random_best}};
  j["ga_from_intact_best"] = {{"evaluations", o.ga_evaluations}, {"best", o.ga_best}};
  // With --no-stop: where the stop rule would have stopped, and the comparisons there (null:
  // it never held within the trials run; absent: the rule was on, and the record above is it).
  if (!request.params.stop_rule) {
    j["at_stop_rule"] = nullptr;
    if (o.at_stop_rule) {
      const AdaptOutcome::AtTrials& a = *o.at_stop_rule;
      j["at_stop_rule"] = {{"trials", a.trials},
                           {"adapted", a.adapted},
                           {"random_elites_best", a.random_best},
                           {"ga_from_intact_best", a.ga_best},
                           {"ga_evaluations", a.ga_evaluations}};
    }
  }
  j["seconds"] = o.seconds;
  WriteFileAtomically(dir.File(kAdaptRecordFile), j.dump(2) + "\n");
  AdaptFigureData figure;
  for (const Trial& t : o.adaptation.trials) {
    figure.trial_distance.push_back(t.distance);
    figure.best_so_far.push_back(t.best);
  }
  figure.intact_best_on_damaged = distance_of(o.intact_best);
  figure.best_elite_on_damaged = distance_of(o.damaged_best);
  figure.damage = o.damage;
  WriteAdaptFigure(dir.temp_path(), figure);
  if (request.movie) {
    const MovieSettings settings = MakeMovieSettings(*request.movie, o.scene_options);
    const auto context = GlContext::CreateOrThrow("cannot render adapt.mp4");
    const auto panel = [&](const std::string& name, int elite) {
      char text[160];
      std::snprintf(text, sizeof text, "%s (elite %d): %.2f in %g on the damaged creature",
                    name.c_str(), elite, distance_of(elite), o.time);
      return MoviePanel{text, PerturbedRestLengths(o.scene.model, o.scene.program,
                                                   o.genomes[static_cast<size_t>(elite)])};
    };
    WriteMovie(dir.File("adapt.mp4"), o.scene,
               {panel("intact best gait", o.intact_best),
                panel("adapted in " + std::to_string(o.trials()) + " trials", o.adapted)},
               settings, "", [&](std::string_view, long long frame, long long total) {
                 if (request.on_progress) request.on_progress("frames of adapt.mp4", frame, total);
               });
  }
  dir.Commit();
}

AdaptOutcome AdaptToFolder(AdaptFile file) {
  IoPaths()
      .Input("--repertoire", file.request.repertoire_dir)
      .OutputFolder("--out", file.out)
      .Check();
  if (!file.no_movie) {
    file.movie.time_flag = "--movie-time";
    file.movie.size_flag = "--movie-size";
    file.movie.cues_flag = "--movie-cues";
    MakeMovieSettings(file.movie, SceneOptions{});  // the flags, before the work
    file.request.movie = file.movie;
  }
  file.request.figure = true;  // WriteAdaptFolder draws adapt.png
  const std::unique_ptr<AtomicDir> folder = TakeAdaptFolder(file.out);
  AdaptOutcome outcome = AdaptToDamage(file.request);
  WriteAdaptFolder(file.request, outcome, *folder);
  return outcome;
}

}  // namespace hexgait
