#include "run/repertoire_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "eval/evaluator.h"
#include "eval/mpi_evaluator.h"
#include "ga/checkpoint.h"
#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "ga/map_elites_checkpoint.h"
#include "motor/assets.h"
#include "motor/leg_targets.h"
#include "record/repertoire_record.h"
#include "render/gl_context.h"
#include "report/repertoire_report.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/movie_request.h"
#include "run/run_folder.h"
#include "run/run_state.h"
#include "run/runtime_needs.h"
#include "run/work_size.h"
#include "search/archive_optimizer.h"
#include "search/ga_optimizer.h"
#include "search/search_driver.h"
#include "sim/lane_refill.h"
#include "simd/isa.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output.h"
#include "util/process_usage.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

namespace fs = std::filesystem;

// The archive's precision from --precision and --no-confirm (docs/speed.md, "The repertoire's
// precision": float evaluates the children at 1.7x double's rate, and double confirms each one
// before it enters, so the repertoire holds only gaits that stand in double).
void ResolveRepertoirePrecision(const RepertoireSettings& opt, const CreatureModel& model,
                                MapElitesParams* p) {
  if (opt.no_confirm && opt.precision != "float") {
    throw InputError("--no-confirm needs --precision float (only float admissions are confirmed)");
  }
  if (opt.precision == "auto") {
    // Under mpirun the confirming double runs would wait on rank 0's threads alone while every
    // other rank idles: double there.
    const bool confirmed = BatchedPathAccepts(model, p->run) && MpiWorldSize() <= 1;
    p->precision = confirmed ? Precision::kFloat : Precision::kDouble;
    p->confirm_in_double = confirmed;
    return;
  }
  p->precision = ParsePrecision(opt.precision);
  p->confirm_in_double = p->precision == Precision::kFloat && !opt.no_confirm;
}

// The paper's GA on the same budget: every individual it evaluates that stands the test goes
// into an archive of its own, so the two methods' gaits are counted the same way.
RepertoireMethod RunGaBaseline(const Scene& scene, const RepertoireSettings& opt,
                               const MapElitesParams& p, const BehaviourDescriptor& descriptor,
                               Archive& archive, const RepertoireObserver& observer) {
  EvolutionParams ga;
  ga.seed = p.seed;
  ga.population = opt.ga_population;
  ga.generations = static_cast<int>(
      std::max<long long>(1, (p.evaluations - ga.population) / (ga.population - 1)));
  // The archive's settings where its algorithm shares them with the GA (MAP-Elites' rates), so
  // the two differ only in what they keep; else the GA's own.
  for (const ParamSpec& spec : kGaParams) {
    if (p.settings.Has(spec.name))
      ga.settings.Set(spec.name, p.settings.Get(spec.name), spec.integer);
  }
  ga.symmetric = p.symmetric;
  ga.threads = p.threads;
  ga.batch_lanes = p.batch_lanes;
  // The GA's gaits are compared with the archive's: in double when the archive's are.
  ga.precision = p.confirm_in_double ? Precision::kDouble : p.precision;
  ga.run = p.run;
  ga.run.stop_at_fall = false;  // the paper's fitness: the distance at the end, fallen or not
  ValidateEvolutionParams(ga);
  RepertoireMethod method;
  method.name = "paper's GA, population " + std::to_string(ga.population);
  method.archive = &archive;
  method.best_fitness = -INFINITY;
  const auto start = Clock::now();
  EvolutionCallbacks callbacks;
  callbacks.on_generation = [&](const GenerationStats& g, const std::vector<Individual>& pop) {
    const size_t first_new =
        g.generation == 0 ? 0 : static_cast<size_t>(ga.settings.Integer("elites"));
    for (size_t i = first_new; i < pop.size(); ++i) {
      ++method.evaluations;
      method.diverged += pop[i].result.diverged ? 1 : 0;
      method.best_fitness = std::max(method.best_fitness, pop[i].fitness);
      OfferToArchive(archive, descriptor, scene.model,
                     Elite{pop[i].genome, pop[i].result, pop[i].fitness, method.evaluations});
    }
    method.history.push_back(StatsOf(archive, method.evaluations, SecondsSince(start)));
    method.history.back().diverged = method.diverged;
    if (observer.progress) {
      observer.progress("GA comparison generations", g.generation + 1, ga.generations + 1);
    }
    if (StopRequested()) throw Stopped("during the GA comparison; no report written");
  };
  const auto evaluator = MakeLocalEvaluator(scene.model, scene.program, EvaluatorConfigFor(ga));
  Evolve(scene.model, scene.program, ga, *evaluator, callbacks);
  method.seconds = SecondsSince(start);
  return method;
}

// repertoire.json's machine_use: readings taken as the search starts, and the record of what
// it used when it ends.
class MachineUseMeter {
 public:
  MachineUseMeter()
      : start_(Clock::now()),
        cpu_seconds_(ProcessCpuSeconds()),
        float_(RefilledLaneSteps(Precision::kFloat)),
        double_(RefilledLaneSteps(Precision::kDouble)) {}

  MachineUseRecord Read() const {
    const LaneSteps f = RefilledLaneSteps(Precision::kFloat);
    const LaneSteps d = RefilledLaneSteps(Precision::kDouble);
    return {SecondsSince(start_),        ProcessCpuSeconds() - cpu_seconds_,
            f.stepped - float_.stepped,  f.running - float_.running,
            d.stepped - double_.stepped, d.running - double_.running};
  }

 private:
  Clock::time_point start_;
  double cpu_seconds_;
  LaneSteps float_, double_;
};

template <class StopPoint>
RepertoireOutcome WriteResults(const Scene& scene, const RepertoireSettings& opt,
                               const MapElitesState& state,
                               const std::vector<RepertoireMethod>& methods,
                               const std::optional<MachineUseRecord>& machine_use,
                               const std::optional<MovieSettings>& movie_settings,
                               const std::string& dir, const std::string& out_dir,
                               Clock::time_point start, const StopPoint& stop_point,
                               const RepertoireObserver& observer) {
  const MapElitesParams& p = state.params;
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(p.descriptor);
  std::error_code ec;
  const std::vector<int> showcase =
      ChooseShowcase(state.archive, descriptor, scene.model, opt.showcase);
  // A folder holds one run's elites: an earlier run's, perhaps more of them, go first.
  fs::remove_all(dir + "elites", ec);
  fs::create_directories(dir + "elites", ec);
  std::vector<MoviePanel> panels;
  for (size_t i = 0; i < showcase.size(); ++i) {
    const Elite& e = *state.archive.at(showcase[i]);
    const std::vector<std::string> lines = BehaviourLines(scene.model, descriptor, e.result);
    std::string comment = "elite " + std::to_string(i + 1) + " of 'hexgait repertoire --seed " +
                          std::to_string(p.seed) + "': cell " + std::to_string(showcase[i]) +
                          ", distance " + std::to_string(e.fitness) + ";";
    for (const std::string& line : lines) comment += " " + line;
    const std::string name = "elite-" + std::to_string(i + 1) + ".genome";
    WriteFileAtomically(dir + "elites/" + name, FormatGenome(e.genome, comment));
    panels.push_back({"elite " + std::to_string(i + 1) + (i == 0 ? " (farthest)" : ""),
                      PerturbedRestLengths(scene.model, scene.program, e.genome), lines});
  }
  const std::string tables = WriteRepertoireReport(
      out_dir, scene.model, scene.program.gene_length_step, descriptor, methods, showcase);

  RepertoireRecord record;
  record.seed = p.seed;
  record.algorithm = p.algorithm;
  record.settings = ParamsToJson(p.settings);
  record.descriptor = p.descriptor;
  record.axes = descriptor.axes(scene.model);
  record.bins = p.bins;
  record.cells = state.archive.cells();
  record.threads = p.threads;
  record.ranks = std::max(1, MpiWorldSize());
  record.time = p.run.duration;
  record.dt = p.run.dt;
  record.precision = PrecisionText(p);
  record.machine_use = machine_use;
  for (const RepertoireMethod& m : methods) {
    const Elite* best = m.archive->Best();
    record.methods.push_back(
        {m.name, m.evaluations, static_cast<long long>(m.archive->filled().size()),
         m.archive->QdScore(), best ? best->fitness : 0.0, m.best_fitness, m.seconds, m.diverged});
  }
  for (size_t i = 0; i < showcase.size(); ++i) {
    const Elite& e = *state.archive.at(showcase[i]);
    ShowcaseRecord shown;
    shown.cell = showcase[i];
    shown.genome = "elites/elite-" + std::to_string(i + 1) + ".genome";
    shown.distance = e.fitness;
    for (size_t leg = 0; leg < scene.model.legs.size(); ++leg) {
      shown.duty_factors.push_back(e.result.DutyFactor(static_cast<int>(leg)));
    }
    shown.found_at = e.found_at;
    record.showcase.push_back(shown);
  }

  if (movie_settings && !panels.empty()) {
    stop_point("the movie grid");
    MovieSettings settings = *movie_settings;
    settings.columns = panels.size() == 1 ? 1 : panels.size() > 4 ? 3 : 2;
    const auto context = GlContext::CreateOrThrow("cannot render the movie grid");
    const MovieStats stats = WriteMovie(dir + "grid.mp4", scene, panels, settings, "",
                                        [&](std::string_view, long long done, long long total) {
                                          if (observer.progress)
                                            observer.progress("frames of grid.mp4", done, total);
                                        });
    if (observer.movie_written) observer.movie_written(dir + "grid.mp4", stats, settings);
    record.movie = RepertoireMovieRecord{"grid.mp4", opt.movie_time, stats.frames};
  }
  stop_point("repertoire.json");
  record.wall_seconds = SecondsSince(start);
  WriteFileAtomically(dir + "repertoire.json", RepertoireRecordJson(record).dump(2) + "\n");
  MarkRunComplete(out_dir, "repertoire");
  return {dir, tables, movie_settings && !panels.empty(), SecondsSince(start)};
}

// The output choices as outputs.json records them, by the flag that sets each.
nlohmann::json OutputsJson(const RepertoireSettings& s) {
  return {{"--compare-ga", s.ga_population}, {"--showcase", s.showcase},
          {"--movie-time", s.movie_time},    {"--movie-size", s.movie_size},
          {"--movie-cues", s.movie_cues},    {"--no-movie", s.no_movie}};
}

// `request` with the output choices recorded in `dir`, except those whose flags were given. A
// folder from before the record keeps the flags as given.
RepertoireSettings WithRecordedOutputs(RepertoireSettings request, const std::string& dir) {
  const std::string path = dir + "/" + kOutputsFile;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return request;
  const nlohmann::json j = ParseJson(ReadTextFile(path), path);
  const auto recorded = [&](const char* flag) {
    const std::vector<std::string>& given = request.output_flags_given;
    return j.contains(flag) && std::find(given.begin(), given.end(), flag) == given.end();
  };
  try {
    if (!j.is_object()) throw InputError(path + ": not a JSON object");
    if (recorded("--compare-ga")) request.ga_population = IntIn(j["--compare-ga"], 0, 1 << 20);
    if (recorded("--showcase")) request.showcase = IntIn(j["--showcase"], 0, 12);
    if (recorded("--movie-time")) request.movie_time = j["--movie-time"].get<double>();
    if (recorded("--movie-size")) request.movie_size = j["--movie-size"].get<std::string>();
    if (recorded("--movie-cues")) request.movie_cues = j["--movie-cues"].get<std::string>();
    if (recorded("--no-movie")) request.no_movie = j["--no-movie"].get<bool>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": " + e.what());
  }
  return request;
}

}  // namespace

RepertoireOutcome RunRepertoire(const RepertoireSettings& request,
                                const RepertoireObserver& observer) {
  const RepertoireSettings opt =
      request.resume_dir.empty() ? request : WithRecordedOutputs(request, request.resume_dir);
  const bool resuming = !opt.resume_dir.empty();
  const std::string out_dir = resuming ? opt.resume_dir : opt.out_dir;
  const char* const out_flag = resuming ? "--resume" : "--out";
  IoPaths paths = SceneInputs(opt.scene);
  paths.OutputFolder(out_flag, out_dir).Check();
  if (opt.ga_population == 1 || opt.ga_population < 0) {
    throw InputError("--compare-ga must be at least 2 (a population), or 0 for no comparison");
  }
  if (opt.showcase < 0 || opt.showcase > 12) throw InputError("--showcase must be in [0, 12]");
  if (!(opt.checkpoint_seconds > 0)) throw InputError("--checkpoint-seconds must be positive");

  SceneOptions scene_options = opt.scene;
  const std::string archive_path =
      resuming ? ResumeStatePath(out_dir, kArchiveFile, opt.run_flags_given) : std::string();
  if (resuming && scene_options.creature_path.empty()) {
    scene_options.creature_path = RecordedBuiltInCreature(archive_path, kMaxArchiveBytes);
  }
  if (resuming && scene_options.damage.empty()) {
    scene_options.damage = RecordedDamage(archive_path, kMaxArchiveBytes);
  }
  const Scene scene = LoadScene(scene_options);
  MapElitesState state;
  if (resuming) {
    state = ParseArchive(ReadTextFile(archive_path, kMaxArchiveBytes), archive_path, scene.model,
                         scene.program);
    state.params.threads = opt.params.threads;
  } else {
    MapElitesParams p = opt.params;
    p.run = MakeRunOptions(opt.scene, opt.time);
    p.run.stop_at_fall = true;
    ResolveRepertoirePrecision(opt, scene.model, &p);
    state = StartArchiveSearch(p, scene.model);
  }
  MapElitesParams& p = state.params;
  p.threads = ResolveThreadCount(p.threads);
  // The movie's settings are checked now, not after the evaluations.
  std::optional<MovieSettings> movie_settings;
  if (!opt.no_movie) {
    MovieRequest movie;
    movie.time = opt.movie_time;
    movie.size = opt.movie_size;
    movie.view.cues = opt.movie_cues;
    movie.time_flag = "--movie-time";
    movie.size_flag = "--movie-size";
    movie.cues_flag = "--movie-cues";
    movie_settings = MakeMovieSettings(movie, scene_options);
    RefuseLongMovieSettings(movie, *movie_settings, scene.program.cycle_period,
                            opt.scene.allow_long);
  }
  // The figures and the movie grid come after every evaluation: what they need is found now.
  // A grid of no elites (--showcase 0) draws nothing.
  RuntimeNeeds needs;
  needs.figures = true;
  if (movie_settings && opt.showcase > 0) needs |= MovieNeeds(*movie_settings);
  CheckRuntime(needs, "cannot render the movie grid");
  const BehaviourDescriptor& descriptor = FindBehaviourDescriptor(p.descriptor);
  {
    // Over an hour of evaluations (both methods, at full length) is refused without --allow-long.
    const double evaluations = static_cast<double>(p.evaluations - state.evaluations) +
                               (opt.ga_population ? p.evaluations : 0);
    const double workers = static_cast<double>(p.threads) * std::max(1, MpiWorldSize());
    RefuseLongEvaluations("--evaluations " + std::to_string(p.evaluations) +
                              (opt.ga_population ? " with --compare-ga" : ""),
                          scene.model, evaluations, p.run, workers, opt.scene.allow_long);
  }
  // The algorithm checks its settings and its saved state here, before anything is written.
  const std::unique_ptr<ArchiveOptimizer> optimizer = MakeArchiveOptimizer(
      SearchScene{scene.model, scene.program, CreatureLabel(scene_options.creature_path)}, state);
  ArchiveOptimizer& search = *optimizer;
  // Before anything is written: under mpirun, the worker ranks serve this evaluator and end here.
  const std::unique_ptr<Evaluator> evaluator =
      MakeEvaluator(scene.model, scene.program, EvaluatorConfigFor(p));
  // Admissions confirmed in double run on this process's threads (under mpirun only when asked
  // for with --precision float: rank 0 then runs them alone).
  const std::unique_ptr<Evaluator> in_double =
      p.confirm_in_double ? MakeDoubleEvaluator(scene.model, scene.program, p) : nullptr;
  // The elites hold the results of the evaluator that admitted them.
  Evaluator& elite_evaluator = in_double ? *in_double : *evaluator;
  if (resuming) {
    // The elites are what the rest of the run breeds from and what the report shows: replayed,
    // not trusted (the checksum guards against damage, not an edit).
    const ReplayCheck check =
        ReplayStoredResults(StoredElites(state.archive, scene.model, scene.program),
                            elite_evaluator, archive_path, kDefaultMaxReplays);
    if (observer.replayed) observer.replayed(check);
  }
  const ResumableFolder folder(out_dir, out_flag, "repertoire", {kArchiveFile, kOutputsFile});
  folder.Write(kOutputsFile, OutputsJson(opt).dump(2) + "\n");
  const std::string dir = out_dir + "/";
  const auto save = [&](const std::string& text) {
    if (text.size() > kMaxArchiveBytes) {
      throw InputError("the archive would be larger than " + MegabytesText(kMaxArchiveBytes) +
                       "; use fewer --bins");
    }
    folder.Write(kArchiveFile, text);
  };

  const auto start = Clock::now();
  if (observer.started) observer.started(state, out_dir, resuming);
  if (in_double) search.ConfirmWith(*in_double);
  SearchHooks hooks;
  hooks.on_progress = observer.progress;
  if (observer.batch) {
    hooks.after_tell = [&] { observer.batch(search.state(), search.Done(), SecondsSince(start)); };
  }
  hooks.save = [&](const std::string& text) {
    save(text);
    if (observer.saved) observer.saved();
  };
  hooks.save_every_seconds = opt.checkpoint_seconds;
  hooks.resume_hint = "; the archive is saved in " + dir + kArchiveFile +
                      "; continue it with: hexgait repertoire --resume " + out_dir;
  std::optional<MachineUseRecord> machine_use;
  if (search.Done()) {
    save(search.Save());
  } else {
    const MachineUseMeter meter;
    RunSearch(search, *evaluator, CandidateDecoder(scene.model, scene.program, search.layout()),
              hooks);
    machine_use = meter.Read();
  }
  state = search.state();
  double seconds = 0;
  for (const ArchiveStats& s : state.history) seconds += s.seconds;
  std::vector<RepertoireMethod> methods;
  {
    RepertoireMethod m;
    m.name = search.kind().title;
    m.archive = &state.archive;
    m.history = state.history;
    m.evaluations = state.evaluations;
    m.diverged = state.history.empty() ? 0 : state.history.back().diverged;
    m.seconds = seconds;
    m.best_fitness = -INFINITY;
    for (int cell : state.archive.filled()) {
      m.best_fitness = std::max(m.best_fitness, state.archive.at(cell)->fitness);
    }
    methods.push_back(std::move(m));
  }
  Archive ga_archive(state.archive.dims(), state.archive.bins());
  if (opt.ga_population > 0) {
    if (observer.comparing) observer.comparing(opt.ga_population);
    methods.push_back(RunGaBaseline(scene, opt, p, descriptor, ga_archive, observer));
  }

  // The archive is complete and saved; a stop from here on keeps it, and --resume writes the rest.
  const auto stop_point = [&](const char* what) {
    if (!StopRequested()) return;
    throw Stopped(std::string("before ") + what + "; the archive is complete in " + dir +
                  kArchiveFile + "; write the rest with: hexgait repertoire --resume " + out_dir);
  };
  stop_point("the report");
  try {
    return WriteResults(scene, opt, state, methods, machine_use, movie_settings, dir, out_dir,
                        start, stop_point, observer);
  } catch (const Stopped&) {
    throw;
  } catch (const InputError&) {
    // A Ctrl-C reaches gnuplot and the encoder too: their failure is the stop's doing.
    if (!StopRequested()) throw;
    stop_point("the rest of the report");
  } catch (const SystemError&) {
    if (!StopRequested()) throw;
    stop_point("the rest of the report");
  }
  throw Stopped("before the rest of the report");  // not reached: stop_point threw
}

LoadedRepertoire LoadRepertoire(const std::string& dir, const SceneOptions& flags,
                                const std::string& flag) {
  RefuseUnfinishedRun(dir, flag, "repertoire");
  const std::string archive_path = dir + "/" + kArchiveFile;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(archive_path, ec)) {
    throw InputError(flag + " '" + dir +
                     "': no archive.json there (make one with 'hexgait repertoire --out DIR')");
  }
  LoadedRepertoire loaded;
  loaded.options = SceneOfFolders(flags, {{flag, dir}});
  loaded.scene = LoadScene(loaded.options);
  try {
    loaded.state = ParseArchive(ReadTextFile(archive_path, kMaxArchiveBytes), archive_path,
                                loaded.scene.model, loaded.scene.program);
  } catch (const InputError& e) {
    throw InputError(flag + ": " + e.what());
  }
  return loaded;
}

}  // namespace hexgait
