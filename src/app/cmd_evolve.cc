// hexgait evolve: the paper's genetic algorithm, with its outputs written to --out DIR.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/assets.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evolve_run.h"
#include "app/progress.h"
#include "app/run_state.h"
#include "app/work_size.h"
#include "eval/mpi_evaluator.h"
#include "ga/checkpoint.h"
#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "sim/batch_evaluate.h"
#include "sim/evaluate.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/folder_lock.h"
#include "util/json_file.h"
#include "util/stop_signal.h"

namespace hexgait {
namespace {

// Flags that change a run's results: a resumed run takes them from its checkpoint instead.
const char* const kRunFlags[] = {"--seed",          "--population",
                                 "--generations",   "--time",
                                 "--symmetric",     "--crossover-rate",
                                 "--mutation-rate", "--initial-mutation-rate",
                                 "--elites",        "--dt",
                                 "--integrator",    "--out",
                                 "--early-stop",    "--precision"};

// Every file evolve writes into its folder.
const char* const kOutputFiles[] = {"checkpoint.json", "fitness.csv", "best.genome", "run.json"};

// evolve writes over a folder only if it is new, empty, or an earlier evolve's (the marker, or
// the checkpoint.json or run.json of a run from before the marker): never over a folder of
// other files, as figures and report refuse one too.
void RefuseForeignFolder(const std::string& folder, const std::string& flag) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(folder, ec)) return;
  if (!fs::is_directory(folder, ec)) {
    throw InputError(flag + " '" + folder + "': is a file, expected a folder");
  }
  if (fs::is_empty(folder, ec)) return;
  for (const char* name : {kEvolveMarker, "checkpoint.json", "run.json"}) {
    if (fs::exists(fs::path(folder) / name, ec)) return;
  }
  throw InputError(flag + " '" + folder + "': folder exists and was not written by hexgait " +
                   "evolve (no " + kEvolveMarker + "); choose a new or empty folder");
}

std::string FitnessCsv(const std::vector<GenerationStats>& history) {
  std::ostringstream out;
  out << "generation,best,mean,worst\n";
  char line[160];
  for (const GenerationStats& g : history) {
    // %.17g round-trips doubles: the file is a bit-exact record of the run.
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g\n", g.generation, g.best, g.mean,
                  g.worst);
    out << line;
  }
  return out.str();
}

std::string FallText(const RunResult& r) {
  if (r.diverged) return "diverged";
  if (!r.fell) return "did not fall";
  char text[64];
  std::snprintf(text, sizeof text, "fell in cycle %d (t = %.0f)", r.fall_cycle, r.fall_time);
  return text;
}

// Refuses a run estimated at over an hour (app/work_size.h): every individual of generation 0
// and all but the elites of each later one, spread over the threads of every MPI rank.
void RefuseLongEvolution(const EvolutionParams& params, bool allow_long) {
  const double evaluations = params.population + static_cast<double>(params.generations) *
                                                     std::max(1, params.population - params.elites);
  const double steps = params.run.duration / params.run.dt;
  const double workers = static_cast<double>(params.threads) * std::max(1, MpiWorldSize());
  char what[192];
  std::snprintf(what, sizeof what,
                "--population %d and --generations %d are %.3g evaluations of %.3g steps on %.0f "
                "threads",
                params.population, params.generations, evaluations, steps, workers);
  RefuseLongRun(what, evaluations * steps * kSecondsPerBatchedStep / workers, allow_long);
}

}  // namespace

void RunEvolve(const EvolveOptions& opt) {
  StopIsPolled();  // stops after the next generation's checkpoint, saying how to resume
  EvolutionParams params = opt.params;
  params.run = MakeRunOptions(opt.scene, opt.time);
  params.run.early_stop = opt.early_stop;
  params.precision = opt.precision == "float" ? Precision::kFloat : Precision::kDouble;
  ValidateEvolutionParams(params);
  // Every input is read and checked before anything is created on disk.
  const bool resuming = !opt.resume_dir.empty();
  {
    // The run's own checkpoint is read and rewritten by design; no other input may be replaced.
    IoPaths paths = SceneInputs(opt.scene);
    for (const char* name : kOutputFiles) {
      paths.Output("--out", (resuming ? opt.resume_dir : opt.out_dir) + "/" + name);
    }
    paths.Check();
  }
  SceneOptions scene_options = opt.scene;
  if (resuming && scene_options.creature_path.empty()) {
    // A run of a built-in creature resumes with it (its checkpoint names it); a creature file
    // must be given again, and the checkpoint's fingerprint checks it is the same.
    std::error_code peek_error;
    const std::string path = opt.resume_dir + "/checkpoint.json";
    if (std::filesystem::is_regular_file(path, peek_error)) {
      const std::string recorded = CheckpointCreature(ReadTextFile(path, kMaxCheckpointBytes));
      if (IsBuiltInCreature(recorded)) scene_options.creature_path = recorded;
    }
  }
  const Scene scene = LoadScene(scene_options);
  std::optional<EvolutionCheckpoint> checkpoint;
  if (resuming) {
    if (!opt.run_flags_given.empty()) {
      throw InputError(opt.run_flags_given.front() +
                       " cannot be combined with --resume: a resumed run keeps the parameters "
                       "in its checkpoint");
    }
    const std::string path = opt.resume_dir + "/checkpoint.json";
    if (!std::filesystem::exists(path)) {
      throw InputError("--resume '" + opt.resume_dir + "': no checkpoint.json there");
    }
    bool unchecked = false;
    checkpoint = ParseCheckpoint(ReadTextFile(path, kMaxCheckpointBytes), path, scene.model,
                                 scene.program, &unchecked);
    if (unchecked) {
      std::fprintf(stderr,
                   "hexgait: warning: %s has no checksum (written by an older hexgait); its "
                   "consistency was checked, but an edit to it cannot be detected\n",
                   path.c_str());
    }
    if (checkpoint->generation >= checkpoint->params.generations) {
      char text[96];
      std::snprintf(text, sizeof text, "': that run is complete (generation %d of %d)",
                    checkpoint->generation, checkpoint->params.generations);
      throw InputError("--resume '" + opt.resume_dir + text);
    }
    params = checkpoint->params;
    params.threads = opt.params.threads;
  }
  const int threads = ResolveThreadCount(params.threads);
  params.threads = threads;
  RefuseLongEvolution(params, opt.scene.allow_long);
  if (MpiRank() > 0 && !opt.local_only) {
    // Under mpirun, the other ranks only evaluate: rank 0 runs the GA and writes every file.
    ServeMpiEvaluations(scene.model, scene.program, EvaluatorConfigFor(params));
    return;
  }
  const std::string out_dir = resuming ? opt.resume_dir : opt.out_dir;
  const char* const out_flag = resuming ? "--resume" : "--out";
  RefuseForeignFolder(out_dir, out_flag);
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw InputError("--out '" + out_dir + "': cannot create folder" +
                     (ec ? ": " + ec.message() : ""));
  }
  const std::string dir = out_dir + "/";
  for (const char* name : kOutputFiles) CheckOutputPath(dir + name, out_flag);
  // Held until the run ends: a second run into this folder is refused, naming this one.
  const FolderLock lock(out_dir, out_flag);
  // Until the last result is written, readers of this folder refuse it: an older run's results
  // may still lie beside this run's checkpoint.
  MarkRunStarted(out_dir);
  const uint64_t fingerprint = SceneFingerprint(scene.model, scene.program);
  // Every evaluation of this run, plain program included, goes through this one evaluator.
  const std::unique_ptr<Evaluator> evaluator =
      opt.local_only ? MakeLocalEvaluator(scene.model, scene.program, EvaluatorConfigFor(params))
                     : MakeEvaluator(scene.model, scene.program, EvaluatorConfigFor(params));
  const auto layout = MakeGenomeLayout(scene.model, scene.program, params.symmetric);

  if (!opt.quiet && resuming) {
    std::printf("resuming %s after generation %d of %d\n", out_dir.c_str(), checkpoint->generation,
                params.generations);
  }
  if (!opt.quiet) {
    std::printf(
        "evolving: population %d, %d generations, seed %llu, %d genes (%d bits), %s, %d "
        "thread%s\n",
        params.population, params.generations, static_cast<unsigned long long>(params.seed),
        layout->num_genes(), layout->num_bits(), PrecisionName(params.precision).c_str(), threads,
        threads == 1 ? "" : "s");
    std::printf("%4s %12s %12s %12s %9s %9s\n", "gen", "best", "mean", "worst", "seconds",
                "elapsed");
    std::fflush(stdout);
  }
  const auto start = std::chrono::steady_clock::now();
  ProgressBar bar("evaluating");
  RunResult unoptimized;
  EvolutionCallbacks callbacks;
  int generation_in_progress = 0;
  callbacks.on_progress = [&](int done, int total) {
    if (opt.quiet) return;
    char detail[64];
    std::snprintf(detail, sizeof detail, "generation %d/%d, %d/%d creatures",
                  generation_in_progress, params.generations, done, total);
    const double fraction =
        (generation_in_progress + static_cast<double>(done) / total) / (params.generations + 1);
    bar.Update(fraction, detail);
  };
  callbacks.on_generation = [&](const GenerationStats& g, const std::vector<Individual>& pop) {
    if (g.generation == 0) unoptimized = pop[0].result;
    generation_in_progress = g.generation + 1;
    if (opt.quiet) return;
    bar.Clear();
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%4d %12.4f %12.4f %12.4f %9.2f %9.2f\n", g.generation, g.best, g.mean, g.worst,
                g.seconds, elapsed);
    std::fflush(stdout);
    // A diverged individual gets fitness 0 and the run goes on, but never silently. Elites
    // (the first `elites` of a bred generation) were reported when they were evaluated.
    const size_t first_new = g.generation == 0 ? 0 : static_cast<size_t>(params.elites);
    for (size_t i = first_new; i < pop.size(); ++i) {
      const RunResult& r = pop[i].result;
      if (!r.diverged) continue;
      std::fprintf(stderr,
                   "hexgait: warning: generation %d, individual %zu diverged at t = %g (step "
                   "%lld): %s; fitness set to 0\n",
                   g.generation, i, r.diverge_time, r.diverge_step, r.diverge_reason.c_str());
    }
  };
  // A checkpoint after every generation; a Ctrl-C or SIGTERM stops right after one.
  callbacks.on_checkpoint = [&](const EvolutionCheckpoint& c) {
    const std::string saved =
        FormatCheckpoint(c, fingerprint, CreatureLabel(scene_options.creature_path));
    // Never write a checkpoint that --resume would refuse.
    if (saved.size() > kMaxCheckpointBytes) {
      throw InputError("the checkpoint of this run would be larger than " +
                       MegabytesText(kMaxCheckpointBytes) + "; use a smaller --population");
    }
    WriteFileAtomically(dir + "checkpoint.json", saved);
    if (StopRequested() && c.generation < params.generations) {
      bar.Clear();
      char text[64];
      std::snprintf(text, sizeof text, "after generation %d of %d", c.generation,
                    params.generations);
      throw Stopped(text + ("; the run is saved in " + dir) +
                    "checkpoint.json; continue it with: hexgait evolve --resume " + out_dir);
    }
  };
  if (resuming) {
    // Generation 0 is not re-run: the unoptimised program's result is recomputed (same bits).
    const RestLengthTable plain = PerturbedRestLengths(scene.model, scene.program, Genome(layout));
    unoptimized = evaluator->Evaluate({&plain, 1}).front();
    generation_in_progress = checkpoint->generation + 1;
  }
  const EvolutionResult result = Evolve(scene.model, scene.program, params, *evaluator, callbacks,
                                        resuming ? &*checkpoint : nullptr);
  bar.Clear();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Individual& best = *result.best;

  WriteFileAtomically(dir + "fitness.csv", FitnessCsv(result.history));
  char comment[160];
  std::snprintf(comment, sizeof comment, "best of 'hexgait evolve --seed %llu': distance %.6f, %s",
                static_cast<unsigned long long>(params.seed), best.fitness,
                FallText(best.result).c_str());
  WriteFileAtomically(dir + "best.genome", FormatGenome(best.genome, comment));

  nlohmann::json run;
  run["hexgait_version"] = HEXGAIT_VERSION;
  run["command"] = "evolve";
  run["seed"] = params.seed;
  run["population"] = params.population;
  run["generations"] = params.generations;
  run["crossover_rate"] = params.crossover_rate;
  run["mutation_rate"] = params.mutation_rate;
  run["initial_mutation_rate"] = params.initial_mutation_rate;
  run["elites"] = params.elites;
  run["symmetric"] = params.symmetric;
  run["genes"] = layout->num_genes();
  run["chromosome_bits"] = layout->num_bits();
  run["threads"] = threads;
  run["batch_lanes"] = params.batch_lanes;
  run["early_stop"] = params.run.early_stop;
  run["time"] = params.run.duration;
  run["dt"] = params.run.dt;
  run["integrator"] = IntegratorName(params.run.integrator);
  run["precision"] = PrecisionName(params.precision);
  run["creature"] = CreatureLabel(scene_options.creature_path);
  // Without --motor a built-in creature runs its own program, a creature file the default's.
  const std::string program_of = IsBuiltInCreature(scene_options.creature_path)
                                     ? scene_options.creature_path
                                     : std::string(kDefaultCreature);
  run["motor"] = scene_options.motor_path.empty() ? "built-in program of " + program_of
                                                  : scene_options.motor_path;
  run["cycle_period"] = scene.program.cycle_period;
  run["evaluations"] = result.total_evaluations;
  run["wall_seconds"] = seconds;
  run["seconds_per_evaluation"] = seconds / result.total_evaluations * threads;
  run["unoptimized"] = RunResultJson(unoptimized);
  run["best"] = RunResultJson(best.result);
  run["best"]["fitness"] = best.fitness;
  run["ratio_best_to_unoptimized"] = unoptimized.distance > 0
                                         ? nlohmann::json(best.fitness / unoptimized.distance)
                                         : nlohmann::json(nullptr);
  nlohmann::json history = nlohmann::json::array();
  for (const GenerationStats& g : result.history) {
    history.push_back({{"generation", g.generation},
                       {"best", g.best},
                       {"mean", g.mean},
                       {"worst", g.worst},
                       {"evaluations", g.evaluations},
                       {"seconds", g.seconds}});
  }
  run["history"] = history;
  WriteFileAtomically(dir + "run.json", run.dump(2) + "\n");
  MarkRunComplete(out_dir);

  if (!opt.quiet) {
    std::printf("\nunoptimized  distance %9.4f  %s\n", unoptimized.distance,
                FallText(unoptimized).c_str());
    std::printf("evolved      distance %9.4f  %s\n", best.fitness, FallText(best.result).c_str());
    if (unoptimized.distance > 0) {
      std::printf("ratio        %.2fx   (paper: 1064 -> 4070, 3.83x)\n",
                  best.fitness / unoptimized.distance);
    }
    std::printf("%d evaluations in %.2f s; wrote %sfitness.csv, %sbest.genome, %srun.json\n",
                result.total_evaluations, seconds, dir.c_str(), dir.c_str(), dir.c_str());
  }
}

void AddEvolveRunOptions(CLI::App* cmd, EvolveOptions& opt) {
  EvolutionParams& p = opt.params;
  cmd->add_option("--population", p.population, "Individuals per generation (paper: 4)")
      ->capture_default_str();
  cmd->add_option("--generations", p.generations,
                  "Generations after the initial population (paper: 10)")
      ->capture_default_str();
  cmd->add_option("--threads", p.threads, "Evaluation threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--batch-lanes", p.batch_lanes,
                  "Creatures simulated in lock-step per batch (0: automatic, 1: one at a time); "
                  "the results do not depend on it")
      ->capture_default_str();
  cmd->add_option("--precision", opt.precision,
                  "Number type of the simulation: double (bit-identical to 'simulate') or float "
                  "(faster; needs --integrator euler; its error is in 'hexgait bench accuracy')")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  cmd->add_option("--time", opt.time, "Simulated time per evaluation (time units)")
      ->capture_default_str();
  cmd->add_flag("--symmetric", p.symmetric,
                "Tie mirror-image springs: 60 genes instead of the paper's 120");
  cmd->add_option("--crossover-rate", p.crossover_rate, "Probability of one-point crossover")
      ->capture_default_str();
  cmd->add_option("--mutation-rate", p.mutation_rate, "Per-bit mutation probability")
      ->capture_default_str();
  cmd->add_option("--initial-mutation-rate", p.initial_mutation_rate,
                  "Per-bit flips that make the initial population from the unoptimised genome")
      ->capture_default_str();
  cmd->add_option("--elites", p.elites, "Best individuals kept unchanged each generation")
      ->capture_default_str();
  cmd->add_flag("--early-stop", opt.early_stop,
                "End an evaluation once the creature has fallen and lain still for a gait cycle");
  AddSceneOptions(cmd, opt.scene);
}

void RegisterEvolve(CLI::App& app) {
  auto opt = std::make_shared<EvolveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "evolve", "Evolve the motor program's rest lengths with the paper's genetic algorithm");
  // CLI11 would wrap a negative number into an unsigned seed; refuse it instead.
  cmd->add_option("--seed", opt->params.seed, "Random seed")->check(kNoSign)->capture_default_str();
  cmd->add_option("--out", opt->out_dir, "Folder for fitness.csv, best.genome and run.json")
      ->capture_default_str();
  cmd->add_option("--resume", opt->resume_dir,
                  "Continue the interrupted run in this folder from its checkpoint.json (same "
                  "--creature and --motor; its parameters come from the checkpoint)");
  cmd->add_flag("--quiet", opt->quiet, "Print nothing; only write the files");
  AddEvolveRunOptions(cmd, *opt);
  cmd->callback([opt, cmd] {
    opt->run_flags_given.clear();
    for (const char* flag : kRunFlags) {
      if (cmd->count(flag) > 0) opt->run_flags_given.push_back(flag);
    }
    RunEvolve(*opt);
  });
}

}  // namespace hexgait
