#include "run/evolve_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

#include "eval/evaluator.h"
#include "eval/mpi_evaluator.h"
#include "ga/checkpoint.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "motor/assets.h"
#include "run/io_paths.h"
#include "run/run_folder.h"
#include "run/run_state.h"
#include "run/work_size.h"
#include "search/search_driver.h"
#include "simd/isa.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

// Every file evolve writes into its folder.
const std::vector<std::string> kOutputFiles = {kCheckpointFile, "fitness.csv", "best.genome",
                                               kRunRecordFile};

std::string FitnessCsv(const std::vector<GenerationStats>& history) {
  std::ostringstream out;
  // diverged: the generation's new simulations that diverged (fitness 0, in the mean and worst).
  out << "generation,best,mean,worst,diverged\n";
  char line[160];
  for (const GenerationStats& g : history) {
    // %.17g round-trips doubles: the file is a bit-exact record of the run.
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%d\n", g.generation, g.best, g.mean,
                  g.worst, g.diverged);
    out << line;
  }
  return out.str();
}

}  // namespace

std::string FallText(const RunResult& r) {
  if (r.diverged) return "diverged";
  if (!r.fell) return "did not fall";
  char text[64];
  std::snprintf(text, sizeof text, "fell in cycle %d (t = %.0f)", r.fall_cycle, r.fall_time);
  return text;
}

namespace {

// Refuses a run estimated at over an hour (run/work_size.h): the evaluations left, spread
// over the threads of every MPI rank.
void RefuseLongEvolution(const GenerationalOptimizer& search, const CreatureModel& model,
                         int threads, bool allow_long) {
  const EvolutionParams& params = search.params();
  const double evaluations = static_cast<double>(search.budget() - search.evaluations());
  const double workers = static_cast<double>(threads) * std::max(1, MpiWorldSize());
  RefuseLongEvaluations("--population " + std::to_string(params.population) +
                            " and --generations " + std::to_string(params.generations),
                        model, evaluations, params.run, workers, allow_long);
}

}  // namespace

EvolutionParams SearchParamsOf(const EvolveSettings& opt) {
  EvolutionParams params = opt.params;
  // The optimizer's own population unless given (CMA-ES's lambda), and its own parameters: the
  // table's defaults, with those given in their place.
  const OptimizerKind& kind = FindOptimizerKind(opt.algorithm);
  if (!opt.population_given) params.population = kind.default_population;
  params.settings = ParamValues::Defaults(*kind.params, opt.settings_given);
  params.run = MakeRunOptions(opt.scene, opt.time);
  params.run.early_stop = opt.early_stop;
  params.precision = ParsePrecision(opt.precision);
  return params;
}

double EstimatedEvolveSeconds(const EvolveSettings& settings, const Scene& scene) {
  const EvolutionParams params = SearchParamsOf(settings);
  const SearchScene search_scene{scene.model, scene.program, ""};
  const auto search = FindOptimizerKind(settings.algorithm).start(search_scene, params);
  return EstimatedSimulationSeconds(scene.model, static_cast<double>(search->budget()),
                                    params.run.duration / params.run.dt, StepPath::kBatched);
}

EvolveOutcome RunEvolve(const EvolveSettings& opt, const EvolveObserver& observer) {
  StopIsPolled();  // stops after the next generation's checkpoint, saying how to resume
  const bool resuming = !opt.resume_dir.empty();
  const std::string out_dir = resuming ? opt.resume_dir : opt.out_dir;
  const char* const out_flag = resuming ? "--resume" : "--out";
  // Every input is read and checked before anything is created on disk.
  {
    // The run's own checkpoint is read and rewritten by design; no other input may be replaced.
    IoPaths paths = SceneInputs(opt.scene);
    for (const std::string& name : kOutputFiles) paths.Output("--out", out_dir + "/" + name);
    paths.Check();
  }
  const EvolutionParams params = SearchParamsOf(opt);
  SceneOptions scene_options = opt.scene;
  std::string state_path;
  if (resuming) {
    state_path = ResumeStatePath(opt.resume_dir, kCheckpointFile, opt.run_flags_given);
    // A run of a built-in creature resumes with it (its checkpoint names it); a creature file
    // must be given again, and the checkpoint's fingerprint checks it is the same.
    if (scene_options.creature_path.empty()) {
      scene_options.creature_path = RecordedBuiltInCreature(state_path, kMaxCheckpointBytes);
    }
    if (scene_options.damage.empty()) {
      scene_options.damage = RecordedDamage(state_path, kMaxCheckpointBytes);
    }
  }
  const Scene scene = LoadScene(scene_options);
  const SearchScene search_scene{scene.model, scene.program,
                                 CreatureLabel(scene_options.creature_path)};
  std::unique_ptr<GenerationalOptimizer> search;
  if (resuming) {
    const std::string text = ReadTextFile(state_path, kMaxCheckpointBytes);
    bool unchecked = false;
    search = CheckpointKind(text).resume(search_scene, text, state_path, &unchecked);
    if (unchecked) {
      std::fprintf(stderr,
                   "hexgait: warning: %s has no checksum (written by an older hexgait); its "
                   "consistency was checked, but an edit to it cannot be detected\n",
                   state_path.c_str());
    }
    if (search->Done()) {
      throw InputError("--resume '" + opt.resume_dir + "': that run is complete (" +
                       search->Position().substr(6) + ")");
    }
  } else {
    search = FindOptimizerKind(opt.algorithm).start(search_scene, params);
  }
  EvolutionParams run_params = search->params();
  run_params.threads = ResolveThreadCount(opt.params.threads);
  run_params.batch_lanes = opt.params.batch_lanes;
  const int threads = run_params.threads;
  CheckEvaluatorConfig(EvaluatorConfigFor(run_params));
  RefuseLongEvolution(*search, scene.model, threads, opt.scene.allow_long);
  // Every evaluation of this run, plain program included, goes through this one evaluator. It
  // comes before anything is written: under mpirun, the worker ranks serve it and end here.
  const std::unique_ptr<Evaluator> evaluator =
      opt.local_only
          ? MakeLocalEvaluator(scene.model, scene.program, EvaluatorConfigFor(run_params))
          : MakeEvaluator(scene.model, scene.program, EvaluatorConfigFor(run_params));
  if (resuming) {
    // The population and best the checkpoint holds steer the rest of the run: replayed, not
    // trusted (its checksum guards against damage, not an edit).
    std::vector<StoredResult> stored;
    const auto add = [&](const std::string& name, const Individual& ind) {
      stored.push_back(
          {name, PerturbedRestLengths(scene.model, scene.program, ind.genome), ind.result});
    };
    const std::vector<Individual>& population = search->generation();
    for (size_t i = 0; i < population.size(); ++i) {
      add("individual " + std::to_string(i) + " of the last generation", population[i]);
    }
    if (search->result().best) add("the best individual so far", *search->result().best);
    const ReplayCheck check =
        ReplayStoredResults(stored, *evaluator, state_path, kDefaultMaxReplays);
    if (observer.replayed) observer.replayed(check);
  }
  const ResumableFolder folder(out_dir, out_flag, "evolve", kOutputFiles,
                               {kCheckpointFile, kRunRecordFile});
  const std::string dir = out_dir + "/";
  const EvolutionParams& p = search->params();
  if (observer.started) observer.started(*search, threads, resuming);
  const auto start = Clock::now();
  SearchHooks hooks;
  hooks.on_progress = observer.progress;
  if (observer.generation) {
    hooks.after_tell = [&] { observer.generation(*search, SecondsSince(start)); };
  }
  // A checkpoint after every generation; a Ctrl-C or SIGTERM stops right after one.
  hooks.save = [&](const std::string& saved) {
    // Never write a checkpoint that --resume would refuse.
    if (saved.size() > kMaxCheckpointBytes) {
      throw InputError("the checkpoint of this run would be larger than " +
                       MegabytesText(kMaxCheckpointBytes) + "; use a smaller --population");
    }
    folder.Write(kCheckpointFile, saved);
    if (observer.saved) observer.saved();
  };
  hooks.resume_hint = "; the run is saved in " + dir +
                      "checkpoint.json; continue it with: hexgait evolve --resume " + out_dir;
  RunSearch(*search, *evaluator, CandidateDecoder(scene.model, scene.program, search->layout()),
            hooks);
  RunResult unoptimized;
  if (const RunResult* plain = search->unoptimized()) {
    unoptimized = *plain;
  } else {
    // Not among this process's evaluations (a resumed run, CMA-ES): run it now (same bits).
    const RestLengthTable table =
        PerturbedRestLengths(scene.model, scene.program, Genome(search->layout()));
    unoptimized = evaluator->Evaluate({&table, 1}).front();
  }
  const double seconds = SecondsSince(start);
  const EvolutionResult& result = search->result();
  const Individual& best = *result.best;
  const OptimizerKind& kind = search->kind();
  const std::string algorithm_flag =
      &kind == OptimizerKinds().front() ? "" : std::string(" --algorithm ") + kind.name;

  folder.Write("fitness.csv", FitnessCsv(result.history));
  char comment[192];
  std::snprintf(comment, sizeof comment,
                "best of 'hexgait evolve%s --seed %llu': distance %.6f, %s", algorithm_flag.c_str(),
                static_cast<unsigned long long>(p.seed), best.fitness,
                FallText(best.result).c_str());
  folder.Write("best.genome", FormatGenome(best.genome, comment));

  RunRecord record;
  record.algorithm = kind.name;
  record.seed = p.seed;
  record.population = p.population;
  record.generations = p.generations;
  record.settings = ParamsToJson(p.settings);
  record.symmetric = p.symmetric;
  record.genes = search->layout()->num_genes();
  record.chromosome_bits = best.genome.continuous() ? 0 : search->layout()->num_bits();
  record.threads = threads;
  record.batch_lanes = run_params.batch_lanes;
  record.early_stop = p.run.early_stop;
  record.time = p.run.duration;
  record.dt = p.run.dt;
  record.integrator = IntegratorName(p.run.integrator);
  record.precision = PrecisionName(p.precision);
  record.creature = CreatureLabel(scene_options.creature_path);
  record.damage = scene.model.damage;
  // Without --motor a built-in creature runs its own program, a creature file the default's.
  const std::string program_of = IsBuiltInCreature(scene_options.creature_path)
                                     ? scene_options.creature_path
                                     : std::string(kDefaultCreature);
  record.motor = scene_options.motor_path.empty() ? "built-in program of " + program_of
                                                  : scene_options.motor_path;
  record.cycle_period = scene.program.cycle_period;
  record.evaluations = result.total_evaluations;
  record.wall_seconds = seconds;
  record.seconds_per_evaluation = seconds / result.total_evaluations * threads;
  record.unoptimized = OutcomeOf(unoptimized);
  record.best = OutcomeOf(best.result);
  record.best_fitness = best.fitness;
  record.history = result.history;
  folder.Write(kRunRecordFile, RunRecordJson(record).dump(2) + "\n");
  folder.Complete();

  return {dir, unoptimized, best.result, record};
}

}  // namespace hexgait
