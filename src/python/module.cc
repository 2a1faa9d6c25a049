// The Python module `hexgait`: the simulator as a batched, deterministic fitness function for
// Python's optimizers, plus traces, stills and movies. It binds the one evaluation seam
// (eval/evaluator.h) and the run layer's option checks (run/), so a genome gives the same bits
// and a mistake the same message as on the command line. InputError becomes ValueError,
// FileError OSError, SystemError (no GL context, FFmpeg missing) RuntimeError; a wrong dtype is a
// TypeError.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "adapt/gaussian_process.h"
#include "eval/evaluator.h"
#include "ga/genome.h"
#include "ga/genome_io.h"
#include "ga/map_elites.h"
#include "model/damage.h"
#include "motor/assets.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/motor_program_io.h"
#include "python/arrays.h"
#include "render/gl_context.h"
#include "run/adapt_run.h"
#include "run/movie_request.h"
#include "run/replay_request.h"
#include "run/scene.h"
#include "run/simulate_run.h"
#include "run/still_request.h"
#include "run/work_size.h"
#include "search/ga_optimizer.h"
#include "search/generational.h"
#include "search/map_elites_optimizer.h"
#include "sim/evaluate.h"
#include "sim/trace.h"
#include "simd/isa.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/stop_signal.h"

namespace hexgait::python {

namespace {

// From a call that released the GIL: raises KeyboardInterrupt (or what a Python signal handler
// raises) if a signal arrived. A few microseconds; called every few milliseconds of work.
void CheckPythonSignals() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

bool OnMainThread() {
  // An integer, not a Python object: a static object would be released after the interpreter.
  static const unsigned long main_thread =
      py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  return PyThread_get_thread_ident() == main_thread;
}

// Runs `work` (with the GIL released unless `keep_gil`) so that a Ctrl-C is heard at once: on
// the main thread, where Python handles signals, SIGINT both trips Python's handler and asks
// hexgait's loops to stop (ForwardedStop; the evaluator polls every 40 steps, inside a batch of
// lanes), and the Stopped that ends the work becomes what Python's handler raises
// (KeyboardInterrupt). Elsewhere the work runs to its end, as Python code there would.
template <class Work>
auto Interruptible(Work&& work, bool keep_gil = false) -> decltype(work()) {
  std::optional<ForwardedStop> forward;
  if (OnMainThread()) forward.emplace();
  try {
    if (keep_gil) return work();
    py::gil_scoped_release release;
    return work();
  } catch (const Stopped&) {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    PyErr_SetNone(PyExc_KeyboardInterrupt);  // the handler did not raise: the work is gone
    throw py::error_already_set();
  }
}

// A creature: a built-in name or a file, kept with the name it was made from (the commands
// take the name; a run records it).
struct PyCreature {
  std::string spec;  // "" = the default creature
  std::shared_ptr<const CreatureModel> model;
};

struct PyMotorProgram {
  std::string path;  // "" = the creature's built-in program
  std::shared_ptr<const MotorProgram> program;
};

// `damage`: as --damage (model/damage.h); the damaged model is what every call given this
// creature simulates, and SceneFor passes it on to the run layer's scene.
PyCreature MakeCreature(const std::optional<std::string>& path, const std::string& damage = "") {
  const std::string spec = path.value_or("");
  if (path && spec.empty()) throw InputError("creature: empty path");
  auto model = std::make_shared<CreatureModel>(LoadCreatureOrDefault(spec));
  ApplyDamage(ParseDamage(damage, *model), model.get());
  return {spec, std::move(model)};
}

// None, a name or path, or a Creature.
PyCreature CreatureArg(const py::handle& arg) {
  if (arg.is_none()) return MakeCreature(std::nullopt);
  if (py::isinstance<PyCreature>(arg)) return arg.cast<PyCreature>();
  if (py::isinstance<py::str>(arg)) return MakeCreature(arg.cast<std::string>());
  throw py::type_error("creature must be None, a name or path, or a hexgait.Creature");
}

PyMotorProgram MakeMotorProgram(const std::optional<std::string>& path,
                                const PyCreature& creature) {
  const std::string p = path.value_or("");
  if (path && p.empty()) throw InputError("motor: empty path");
  return {p, std::make_shared<MotorProgram>(
                 LoadMotorProgramOrDefault(p, *creature.model, creature.spec))};
}

PyMotorProgram MotorArg(const py::handle& arg, const PyCreature& creature) {
  if (arg.is_none()) return MakeMotorProgram(std::nullopt, creature);
  if (py::isinstance<PyMotorProgram>(arg)) return arg.cast<PyMotorProgram>();
  if (py::isinstance<py::str>(arg)) return MakeMotorProgram(arg.cast<std::string>(), creature);
  throw py::type_error("motor must be None, a path, or a hexgait.MotorProgram");
}

SceneOptions SceneFor(const PyCreature& creature, const PyMotorProgram& motor, double dt,
                      const std::string& integrator, bool allow_long) {
  SceneOptions scene;
  scene.creature_path = creature.spec;
  scene.motor_path = motor.path;
  scene.damage = creature.model->damage;
  scene.dt = dt;
  scene.integrator = integrator;
  scene.allow_long = allow_long;
  return scene;
}

// What evaluate() computed, whole: the dict's arrays are for reading, this is what Search.tell
// takes, so a Python loop continues with the command's bits.
struct PyRunResults {
  std::vector<RunResult> results;
};

// A whole population per call; the GIL is released while it runs, and one call at a time per
// evaluator (its threads are its own).
class PyEvaluator {
 public:
  PyEvaluator(const py::handle& creature, const py::handle& motor, double time, double dt,
              const std::string& integrator, const std::string& precision, int threads,
              bool symmetric, int batch_lanes, bool allow_long, bool stop_at_fall)
      : creature_(CreatureArg(creature)),
        motor_(MotorArg(motor, creature_)),
        allow_long_(allow_long) {
    EvaluatorConfig config;
    config.run = MakeRunOptions(SceneFor(creature_, motor_, dt, integrator, allow_long), time);
    config.run.stop_at_fall = stop_at_fall;
    config.precision = ParsePrecision(precision);
    config.threads = threads;
    config.batch_lanes = batch_lanes;
    CheckEvaluatorConfig(config);  // the commands' limits, with their messages
    config_ = config;
    layout_ = MakeGenomeLayout(*creature_.model, *motor_.program, symmetric);
    geometric_ = GeometricRestLengths(*creature_.model, *motor_.program);
    evaluator_ = MakeLocalEvaluator(*creature_.model, *motor_.program, config);
  }

  py::dict Evaluate(const py::handle& genomes) {
    int rows = 0;
    const std::vector<int8_t> genes =
        GenesFromArray(genomes, layout_->num_genes(), "genomes", &rows);
    std::vector<RestLengthTable> tables;
    tables.reserve(rows);
    Genome genome(layout_);
    for (int r = 0; r < rows; ++r) {
      for (int g = 0; g < layout_->num_genes(); ++g) {
        genome.set_gene(g, genes[static_cast<size_t>(r) * layout_->num_genes() + g]);
      }
      tables.push_back(PerturbedRestLengths(geometric_, *creature_.model, *motor_.program, genome));
    }
    return Run(tables);
  }

  py::dict EvaluateOffsets(const py::handle& offsets) {
    int rows = 0;
    const std::vector<double> values =
        OffsetsFromArray(offsets, layout_->num_genes(), "offsets", &rows);
    std::vector<RestLengthTable> tables;
    tables.reserve(rows);
    for (int r = 0; r < rows; ++r) {
      tables.push_back(
          OffsetRestLengths(geometric_, *creature_.model, *layout_,
                            values.data() + static_cast<size_t>(r) * layout_->num_genes()));
    }
    return Run(tables);
  }

  int genes() const { return layout_->num_genes(); }
  double gene_length_step() const { return motor_.program->gene_length_step; }
  std::vector<std::pair<std::string, std::string>> gene_names() const {
    std::vector<std::pair<std::string, std::string>> names;
    for (int g = 0; g < layout_->num_genes(); ++g) {
      names.emplace_back(layout_->spring_name[g], layout_->position_name[g]);
    }
    return names;
  }
  std::string Describe() const { return evaluator_->Describe(); }
  const PyCreature& creature() const { return creature_; }
  const PyMotorProgram& motor() const { return motor_; }
  const EvaluatorConfig& config() const { return config_; }
  const std::shared_ptr<const GenomeLayout>& layout() const { return layout_; }

 private:
  // The population in slices of about a quarter of a second each (EvaluateInSlices), the GIL
  // released while they run: between slices a Ctrl-C raises KeyboardInterrupt (Python's handler
  // runs only when the GIL is held).
  py::dict Run(const std::vector<RestLengthTable>& tables) {
    RefuseLongBatch(tables.size());
    std::vector<RunResult> results;
    results = Interruptible([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      return EvaluateInSlices(*evaluator_, tables, config_.threads, 0.25,
                              [](int, int) { CheckPythonSignals(); });
    });
    py::dict out = ResultsToDict(results, static_cast<int>(creature_.model->legs.size()));
    // Every field of every result, exactly, for Search.tell.
    out["results"] = py::cast(PyRunResults{std::move(results)});
    return out;
  }

  // The commands' over-an-hour rule (run/work_size.h) for a whole population.
  void RefuseLongBatch(size_t creatures) const {
    const double steps = config_.run.duration / config_.run.dt;
    const double threads = ResolveThreadCount(config_.threads);
    char what[160];
    std::snprintf(what, sizeof what, "%zu creatures of %.3g steps on %.0f threads", creatures,
                  steps, threads);
    RefuseLongRun(what,
                  EstimatedSimulationSeconds(*creature_.model, static_cast<double>(creatures),
                                             steps, StepPath::kBatched, threads),
                  allow_long_);
  }

  PyCreature creature_;
  PyMotorProgram motor_;
  bool allow_long_ = false;
  EvaluatorConfig config_;
  std::shared_ptr<const GenomeLayout> layout_;
  RestLengthTable geometric_;
  std::unique_ptr<Evaluator> evaluator_;
  std::mutex mutex_;
};

// hexgait.Search: an optimizer of the search driver (search/optimizer.h) on an Evaluator's
// creature, program and run settings, driven from Python by ask() and tell(). The same
// optimizer objects the commands run, so the same seed and settings give the same bits.
class PySearch {
 public:
  PySearch(const std::string& algorithm, const PyEvaluator& evaluator, uint64_t seed,
           std::optional<int> population, int generations, double sigma, double crossover_rate,
           double mutation_rate, double initial_mutation_rate, int elites, long long evaluations,
           int batch, const std::string& descriptor, int bins, bool confirm_in_double)
      : model_(evaluator.creature().model),
        program_(evaluator.motor().program),
        legs_(static_cast<int>(model_->legs.size())),
        algorithm_(algorithm) {
    const EvaluatorConfig& config = evaluator.config();
    const bool symmetric = evaluator.layout()->symmetric;
    const std::string creature = CreatureLabel(evaluator.creature().spec);
    if (algorithm == "map-elites") {
      MapElitesParams p;
      p.seed = seed;
      p.evaluations = evaluations;
      p.batch = batch;
      p.descriptor = descriptor;
      p.bins = bins;
      p.crossover_rate = crossover_rate;
      p.mutation_rate = mutation_rate;
      p.initial_mutation_rate = initial_mutation_rate;
      p.symmetric = symmetric;
      p.precision = config.precision;
      p.confirm_in_double = confirm_in_double;
      p.run = config.run;
      ValidateMapElitesParams(p, *model_);
      map_elites_ = std::make_unique<MapElitesOptimizer>(*model_, *program_,
                                                         StartMapElites(p, *model_), creature);
      optimizer_ = map_elites_.get();
      if (confirm_in_double) {  // as `hexgait repertoire`: a double evaluator of the same run
        in_double_ = MakeDoubleEvaluator(*model_, *program_, p);
        map_elites_->ConfirmWith(*in_double_);
      }
      return;
    }
    if (confirm_in_double) throw InputError("confirm_in_double is for 'map-elites' only");
    EvolutionParams p;
    p.seed = seed;
    p.population = population.value_or(algorithm == "ga" ? 4 : 0);
    p.generations = generations;
    p.sigma = sigma;
    p.crossover_rate = crossover_rate;
    p.mutation_rate = mutation_rate;
    p.initial_mutation_rate = initial_mutation_rate;
    p.elites = elites;
    p.symmetric = symmetric;
    p.precision = config.precision;
    p.run = config.run;
    std::string names = "map-elites";
    for (const OptimizerKind* kind : OptimizerKinds()) names += std::string(", ") + kind->name;
    const OptimizerKind* kind = nullptr;
    for (const OptimizerKind* k : OptimizerKinds()) {
      if (algorithm == k->name) kind = k;
    }
    if (!kind) throw InputError("algorithm '" + algorithm + "' is not one of " + names);
    generational_ = kind->start(SearchScene{*model_, *program_, creature}, p);
    optimizer_ = generational_.get();
  }

  py::array_t<double> Ask() {
    if (optimizer_->Done()) throw InputError("ask: the search is done (its budget is spent)");
    const Candidates& c = optimizer_->Ask();
    py::array_t<double> out({static_cast<py::ssize_t>(c.size()), static_cast<py::ssize_t>(c.dims)});
    std::copy(c.offsets.begin(), c.offsets.end(), out.mutable_data());
    return out;
  }

  void Tell(const py::dict& results) {
    if (!results.contains("results") || !py::isinstance<PyRunResults>(results["results"])) {
      throw py::type_error("tell: expected the dict Evaluator.evaluate_offsets returned");
    }
    // MAP-Elites confirming in double runs simulations here; a Ctrl-C drops the batch whole
    // (the state stays as before the call). The GIL stays held: a Search is not thread-safe.
    const std::vector<RunResult>& told = results["results"].cast<const PyRunResults&>().results;
    Interruptible([&] { optimizer_->Tell(told); }, /*keep_gil=*/true);
  }

  bool done() const { return optimizer_->Done(); }
  long long evaluations() const { return optimizer_->evaluations(); }
  long long budget() const { return optimizer_->budget(); }
  std::string Save() const { return optimizer_->Save(); }

  // The best individual so far: its offsets, genes (None for a continuous genome) and result.
  py::object Best() const {
    const Genome* genome = nullptr;
    const RunResult* result = nullptr;
    if (generational_ && generational_->result().best) {
      genome = &generational_->result().best->genome;
      result = &generational_->result().best->result;
    } else if (map_elites_ && map_elites_->state().archive.Best()) {
      genome = &map_elites_->state().archive.Best()->genome;
      result = &map_elites_->state().archive.Best()->result;
    }
    if (!genome) return py::none();
    py::dict best = ResultToDict(*result, legs_);
    py::array_t<double> offsets(genome->num_genes());
    for (int g = 0; g < genome->num_genes(); ++g) {
      offsets.mutable_at(g) = genome->Offset(g, program_->gene_length_step);
    }
    best["offsets"] = offsets;
    if (genome->continuous()) {
      best["genes"] = py::none();
    } else {
      py::array_t<int8_t> genes(genome->num_genes());
      std::copy(genome->genes().begin(), genome->genes().end(), genes.mutable_data());
      best["genes"] = genes;
    }
    return best;
  }

  // One dict per generation (best, mean, worst) or per MAP-Elites batch (filled, qd_score,
  // best).
  py::list History() const {
    py::list out;
    if (generational_) {
      for (const GenerationStats& g : generational_->result().history) {
        py::dict d;
        d["generation"] = g.generation;
        d["best"] = g.best;
        d["mean"] = g.mean;
        d["worst"] = g.worst;
        d["evaluations"] = g.evaluations;
        d["diverged"] = g.diverged;
        out.append(d);
      }
    } else {
      for (const ArchiveStats& a : map_elites_->state().history) {
        py::dict d;
        d["evaluations"] = a.evaluations;
        d["filled"] = a.filled;
        d["qd_score"] = a.qd_score;
        d["best"] = a.best;
        d["diverged"] = a.diverged;
        out.append(d);
      }
    }
    return out;
  }

  // MAP-Elites: one dict per filled cell, in the order cells were first filled.
  py::list ArchiveList() const {
    if (!map_elites_) throw InputError("archive: only a map-elites search has an archive");
    py::list out;
    const Archive& archive = map_elites_->state().archive;
    for (int cell : archive.filled()) {
      const Elite& e = *archive.at(cell);
      py::dict d;
      d["cell"] = cell;
      py::array_t<int8_t> genes(e.genome.num_genes());
      std::copy(e.genome.genes().begin(), e.genome.genes().end(), genes.mutable_data());
      d["genes"] = genes;
      d["distance"] = e.fitness;
      d["found_at"] = e.found_at;
      out.append(d);
    }
    return out;
  }

  std::string Describe() const {
    return algorithm_ + ", " + std::to_string(optimizer_->evaluations()) + " of " +
           std::to_string(optimizer_->budget()) + " evaluations";
  }

 private:
  std::shared_ptr<const CreatureModel> model_;
  std::shared_ptr<const MotorProgram> program_;
  int legs_;
  std::string algorithm_;
  std::unique_ptr<GenerationalOptimizer> generational_;
  std::unique_ptr<Evaluator> in_double_;  // confirms map-elites admissions: outlives map_elites_
  std::unique_ptr<MapElitesOptimizer> map_elites_;
  Optimizer* optimizer_ = nullptr;
};

// A genome from Python: None (unoptimized), a genome file, or an array of genes whose length
// picks the layout (full or symmetric).
Genome GenomeArg(const py::handle& arg, const PyCreature& creature, const PyMotorProgram& motor) {
  const auto layout = [&](bool symmetric) {
    return MakeGenomeLayout(*creature.model, *motor.program, symmetric);
  };
  if (arg.is_none()) return Genome(layout(false));
  if (py::isinstance<py::str>(arg)) {
    const std::string path = arg.cast<std::string>();
    if (path.empty()) throw InputError("genome: empty path");
    const std::string text = ReadTextFile(path);
    return ParseGenome(text, path, layout(GenomeFileIsSymmetric(text, path)));
  }
  const auto full = layout(false);
  const auto symmetric = layout(true);
  const py::array a = py::array::ensure(arg);
  const bool is_symmetric = a && a.ndim() == 1 && a.shape(0) == symmetric->num_genes();
  Genome genome(is_symmetric ? symmetric : full);
  int rows = 0;
  const std::vector<int8_t> genes = GenesFromArray(arg, genome.num_genes(), "genome", &rows);
  if (rows != 1) throw py::value_error("genome must be one genome, a 1-D array");
  for (int g = 0; g < genome.num_genes(); ++g) genome.set_gene(g, genes[g]);
  return genome;
}

py::array_t<int8_t> GenesToArray(const Genome& genome) {
  py::array_t<int8_t> out(genome.num_genes());
  std::copy(genome.genes().begin(), genome.genes().end(), out.mutable_data());
  return out;
}

// The genes as int8, or a continuous genome's offsets (CMA-ES's best) as float64 in length units,
// ready for evaluate_offsets.
py::array LoadGenome(const std::string& path, const py::handle& creature_arg,
                     const py::handle& motor_arg) {
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  if (path.empty()) throw InputError("genome: empty path");
  const Genome genome = GenomeArg(py::str(path), creature, motor);
  if (!genome.continuous()) return GenesToArray(genome);
  py::array_t<double> offsets(static_cast<py::ssize_t>(genome.offsets().size()));
  std::copy(genome.offsets().begin(), genome.offsets().end(), offsets.mutable_data());
  return offsets;
}

void SaveGenome(const std::string& path, const py::handle& genome_arg,
                const py::handle& creature_arg, const py::handle& motor_arg,
                const std::string& comment) {
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  if (genome_arg.is_none() || py::isinstance<py::str>(genome_arg)) {
    throw py::type_error("genome must be an integer array of genes");
  }
  const Genome genome = GenomeArg(genome_arg, creature, motor);
  CheckOutputPath(path, "genome file");
  WriteFileAtomically(path, FormatGenome(genome, comment));
}

// One run as `hexgait simulate` makes it (run/simulate_run.h), as a dict of arrays.
py::dict SimulateRun(const py::handle& genome_arg, const py::handle& creature_arg,
                     const py::handle& motor_arg, double time, double dt,
                     const std::string& integrator, double interval,
                     const std::optional<std::vector<double>>& positions_at, bool allow_long) {
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  const RunOptions run =
      MakeRunOptions(SceneFor(creature, motor, dt, integrator, allow_long), time);
  const Genome genome = GenomeArg(genome_arg, creature, motor);
  const Scene scene{*creature.model, *motor.program};
  SimulateRequest request;
  request.interval = interval;
  request.positions_at = positions_at.value_or(std::vector<double>{});
  const SimulatedRun simulated = Interruptible([&] {
    return SimulateGenome(scene, genome, run, request, "interval",
                          [](long long, long long) { CheckPythonSignals(); });
  });
  const RunResult& result = simulated.result;
  const CreatureModel& model = *creature.model;
  py::dict d = ResultToDict(result, static_cast<int>(model.legs.size()));

  const std::vector<TraceSample>& samples = simulated.samples;
  const auto k = static_cast<py::ssize_t>(samples.size());
  const auto legs = static_cast<py::ssize_t>(model.legs.size());
  py::array_t<double> t(k), centre({k, py::ssize_t{3}}), lowest(k), tilt(k), pitch(k), roll(k);
  py::array_t<bool> feet({k, legs});
  for (py::ssize_t i = 0; i < k; ++i) {
    const TraceSample& s = samples[static_cast<size_t>(i)];
    t.mutable_at(i) = s.time;
    for (int c = 0; c < 3; ++c) centre.mutable_at(i, c) = s.centre[c];
    lowest.mutable_at(i) = s.lowest_body;
    tilt.mutable_at(i) = s.tilt_degrees;
    pitch.mutable_at(i) = s.pitch_degrees;
    roll.mutable_at(i) = s.roll_degrees;
    for (py::ssize_t leg = 0; leg < legs; ++leg)
      feet.mutable_at(i, leg) = (s.feet_on_ground >> leg) & 1u;
  }
  d["time"] = t;
  d["centre"] = centre;
  d["lowest_body"] = lowest;
  d["tilt_degrees"] = tilt;
  d["pitch_degrees"] = pitch;
  d["roll_degrees"] = roll;
  d["feet_on_ground"] = feet;
  std::vector<std::string> leg_names;
  for (const Leg& leg : model.legs) leg_names.push_back(leg.name);
  d["legs"] = leg_names;

  // positions[i] belongs to positions_at[i].
  const auto particles = static_cast<py::ssize_t>(model.num_particles());
  const auto m = static_cast<py::ssize_t>(simulated.positions.size());
  py::array_t<double> positions({m, particles, py::ssize_t{3}});
  for (py::ssize_t i = 0; i < m; ++i) {
    const std::vector<double>& xyz = simulated.positions[static_cast<size_t>(i)];
    std::copy(xyz.begin(), xyz.end(), positions.mutable_data() + i * particles * 3);
  }
  d["positions"] = positions;
  py::array_t<double> positions_time(m);
  for (py::ssize_t i = 0; i < m; ++i) {
    positions_time.mutable_at(i) = simulated.position_steps[static_cast<size_t>(i)] * run.dt;
  }
  d["positions_time"] = positions_time;
  return d;
}

// A text option from Python: None is the default (""); an empty string is refused, as the
// command line refuses an empty value.
std::string TextArg(const py::handle& arg, const char* name) {
  if (arg.is_none()) return "";
  if (!py::isinstance<py::str>(arg)) throw py::type_error(std::string(name) + " must be a string");
  std::string text = arg.cast<std::string>();
  if (text.empty()) throw InputError(std::string(name) + ": empty value");
  return text;
}

// cues='footprints,strip' or ['footprints', 'strip'].
std::string CuesArg(const py::handle& arg) {
  if (py::isinstance<py::list>(arg) || py::isinstance<py::tuple>(arg)) {
    std::string text;
    for (const auto& item : arg) {
      if (!text.empty()) text += ',';
      text += TextArg(item, "cues");
    }
    return text;
  }
  return TextArg(arg, "cues");
}

// gl='egl' or 'osmesa' for this call; None: HEXGAIT_GL, else the first that works. A choice
// of an earlier call does not stick.
void ChooseGlBackend(const py::handle& arg) {
  const std::string name = TextArg(arg, "gl");
  const std::vector<std::string> names = GlBackendNames();
  if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError("gl '" + name + "': unknown OpenGL backend (use " + list + ")");
  }
  SetGlBackend(name);
}

ViewRequest ViewArgs(const py::handle& view, const py::handle& camera, const py::handle& track,
                     const py::handle& cues) {
  return {TextArg(view, "view"), TextArg(camera, "camera"), TextArg(track, "track"), CuesArg(cues)};
}

// The genome of a still or a movie and the caption's name for it.
Genome PictureGenome(const py::handle& genome_arg, bool unoptimized, const PyCreature& creature,
                     const PyMotorProgram& motor, std::string* label) {
  if (unoptimized && !genome_arg.is_none()) {
    throw InputError("unoptimized=True and genome= exclude each other");
  }
  if (genome_arg.is_none()) {
    *label = "unoptimized";
  } else if (py::isinstance<py::str>(genome_arg)) {
    *label = "genome " + genome_arg.cast<std::string>();
  } else {
    *label = "genome";
  }
  return GenomeArg(genome_arg, creature, motor);
}

py::array_t<uint8_t> RenderStillFrame(const py::handle& genome_arg, const py::handle& creature_arg,
                                      const py::handle& motor_arg, bool unoptimized, double time,
                                      const std::string& size, const py::handle& view,
                                      const py::handle& camera, const py::handle& track,
                                      const py::handle& cues, bool no_overlay, bool no_shadow,
                                      int msaa, double dt, const std::string& integrator,
                                      bool allow_long, const py::handle& gl) {
  StillRequest request;
  request.time = time;
  request.size = size;
  request.no_overlay = no_overlay;
  request.no_shadow = no_shadow;
  request.msaa = msaa;
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  const StillSettings settings =
      MakeStillSettings(request, SceneFor(creature, motor, dt, integrator, allow_long));
  ChooseGlBackend(gl);
  std::string label;
  const Genome genome = PictureGenome(genome_arg, unoptimized, creature, motor, &label);
  const Scene scene{*creature.model, *motor.program};
  const Image image = Interruptible([&] {
    return RenderStill(scene, genome, settings, [](long long, long long) { CheckPythonSignals(); });
  });
  py::array_t<uint8_t> rgb({py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{3}});
  uint8_t* dst = rgb.mutable_data();
  for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p) {
    std::copy_n(image.rgba.data() + 4 * p, 3, dst + 3 * p);
  }
  return rgb;
}

py::array_t<double> Float64Array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

// adapt()'s creature and motor program as the command's --creature and --motor take them: None
// is what the repertoire recorded; a damaged Creature is refused (the damage is damage=).
std::string AdaptCreatureSpec(const py::handle& arg) {
  if (arg.is_none()) return "";
  const PyCreature creature = CreatureArg(arg);
  if (!creature.model->damage.empty()) {
    throw InputError(
        "creature: give the intact creature the repertoire was made on; the damage to adapt to "
        "is damage=");
  }
  return creature.spec.empty() ? creature.model->name : creature.spec;
}

std::string AdaptMotorPath(const py::handle& arg) {
  if (arg.is_none()) return "";
  if (py::isinstance<PyMotorProgram>(arg)) return arg.cast<PyMotorProgram>().path;
  if (py::isinstance<py::str>(arg)) {
    const std::string path = arg.cast<std::string>();
    if (path.empty()) throw InputError("motor: empty path");
    return path;
  }
  throw py::type_error("motor must be None, a path, or a hexgait.MotorProgram");
}

py::dict AdaptToDamageDict(const std::string& repertoire, const std::string& damage, int trials,
                           double stop, double kappa, double length_scale, double signal_variance,
                           double noise, uint64_t seed, int threads, const py::handle& creature,
                           const py::handle& motor) {
  AdaptRequest request;
  request.repertoire_dir = repertoire;
  request.creature_path = AdaptCreatureSpec(creature);
  request.motor_path = AdaptMotorPath(motor);
  request.damage = damage;
  request.params.max_trials = trials;
  request.params.stop_fraction = stop;
  request.params.kappa = kappa;
  request.params.gp.length_scale = length_scale;
  request.params.gp.signal_variance = signal_variance;
  request.params.gp.noise = noise;
  request.seed = seed;
  request.threads = threads;
  // Between pieces of a fraction of a second each, a Ctrl-C raises KeyboardInterrupt.
  request.on_progress = [](const std::string&, int, int) { CheckPythonSignals(); };
  const AdaptOutcome o = Interruptible([&] { return AdaptToDamage(request); });
  py::list trial_list;
  for (const Trial& t : o.adaptation.trials) {
    py::dict d;
    d["elite"] = t.elite;
    d["cell"] = o.cells[static_cast<size_t>(t.elite)];
    d["predicted_mean"] = t.predicted_mean;
    d["predicted_std"] = t.predicted_std;
    d["distance"] = t.distance;
    d["best"] = t.best;
    d["best_elite"] = t.best_elite;
    d["fell"] = o.trial_runs[trial_list.size()].fell;
    d["diverged"] = o.trial_runs[trial_list.size()].diverged;
    trial_list.append(d);
  }
  std::vector<double> damaged;
  py::array_t<bool> fell(static_cast<py::ssize_t>(o.damaged.size()));
  py::array_t<bool> diverged(static_cast<py::ssize_t>(o.damaged.size()));
  for (size_t e = 0; e < o.damaged.size(); ++e) {
    damaged.push_back(o.damaged[e].distance);
    fell.mutable_at(static_cast<py::ssize_t>(e)) = o.damaged[e].fell;
    diverged.mutable_at(static_cast<py::ssize_t>(e)) = o.damaged[e].diverged;
  }
  py::dict out;
  out["damage"] = o.damage;
  out["trials"] = trial_list;
  out["stopped"] = TrialStopText(o.adaptation.stop);
  out["adapted"] = o.adapted;
  out["adapted_distance"] = o.adaptation.trials.back().best;
  out["intact_best"] = o.intact_best;
  out["damaged_best"] = o.damaged_best;
  out["random_best"] = o.random_best;
  out["ga_best"] = o.ga_best;
  out["ga_evaluations"] = o.ga_evaluations;
  out["cells"] = Float64Array(std::vector<double>(o.cells.begin(), o.cells.end()));
  out["intact_distance"] = Float64Array(o.prior);
  out["damaged_distance"] = Float64Array(damaged);
  out["damaged_fell"] = fell;
  out["damaged_diverged"] = diverged;
  return out;
}

std::string ReplayPageText(const py::handle& genome_arg, const py::handle& creature_arg,
                           const py::handle& motor_arg, bool unoptimized, double time,
                           const py::handle& view, const py::handle& camera,
                           const py::handle& track, const py::handle& cues, bool no_overlay,
                           bool no_shadow, double dt, const std::string& integrator,
                           bool allow_long) {
  ReplayRequest request;
  request.time = time;
  request.no_overlay = no_overlay;
  request.no_shadow = no_shadow;
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  const Scene scene{*creature.model, *motor.program};
  const ReplaySettings settings =
      MakeReplaySettings(request, SceneFor(creature, motor, dt, integrator, allow_long), scene);
  if (!settings.decimation.empty()) {
    if (PyErr_WarnEx(PyExc_UserWarning, settings.decimation.c_str(), 1) < 0) {
      throw py::error_already_set();  // warnings turned into errors
    }
  }
  std::string label;
  const Genome genome = PictureGenome(genome_arg, unoptimized, creature, motor, &label);
  return Interruptible([&] {
    return ReplayHtml(scene, genome, settings, label,
                      [](long long, long long) { CheckPythonSignals(); });
  });
}

std::string RenderMovieFile(const std::string& path, const py::handle& genome_arg,
                            const py::handle& creature_arg, const py::handle& motor_arg,
                            bool unoptimized, double time, const std::string& size, int fps,
                            double speed, int msaa, const std::string& preset, int crf,
                            bool overlay, bool no_shadow, bool no_caption, const py::handle& view,
                            const py::handle& camera, const py::handle& track,
                            const py::handle& cues, const py::handle& frames, double dt,
                            const std::string& integrator, bool allow_long, const py::handle& gl) {
  MovieRequest request;
  request.time = time;
  request.size = size;
  request.fps = fps;
  request.speed = speed;
  request.msaa = msaa;
  request.preset = preset;
  request.crf = crf;
  request.overlay = overlay;
  request.no_shadow = no_shadow;
  request.no_caption = no_caption;
  request.frames_dir = TextArg(frames, "frames");
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  const SceneOptions scene_options = SceneFor(creature, motor, dt, integrator, allow_long);
  const MovieSettings settings = MakeMovieSettings(request, scene_options);
  ChooseGlBackend(gl);
  if (path.empty()) throw InputError("path: empty value");
  IoPaths paths = SceneInputs(scene_options);
  if (py::isinstance<py::str>(genome_arg)) paths.Input("genome", genome_arg.cast<std::string>());
  paths.Output("path", path).Check();
  CheckExtension(path, ".mp4", "path");
  CheckOutputPath(path, "path");
  const Scene scene{*creature.model, *motor.program};
  RefuseLongMovieSettings(request, settings, scene.program.cycle_period, allow_long);
  std::string label;
  const Genome genome = PictureGenome(genome_arg, unoptimized, creature, motor, &label);
  // A Ctrl-C ends the call; the unfinished movie is removed (VideoEncoder).
  Interruptible([&] {
    return RenderGaitMovie(path, scene, genome, label, settings, request.frames_dir,
                           [](long long, long long) { CheckPythonSignals(); });
  });
  return path;
}

// The prior means for `n` points: None is zero at every point (a plain GP on the values).
Eigen::VectorXd PriorOrZero(const std::optional<Eigen::VectorXd>& prior, Eigen::Index n) {
  return prior ? *prior : Eigen::VectorXd(Eigen::VectorXd::Zero(n));
}

}  // namespace

}  // namespace hexgait::python

PYBIND11_MODULE(hexgait, m) {
  using namespace hexgait;
  using namespace hexgait::python;
  m.doc() =
      "hexgait: Nikovski's six-legged mass-spring creature as a fast, deterministic fitness "
      "function (Evaluator), with traces (simulate), stills and movies. Genes are the paper's "
      "4-bit integers in [-8, 7]; offsets are rest-length changes in length units.";
  m.attr("__version__") = HEXGAIT_VERSION;

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SystemError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  py::class_<PyCreature>(
      m, "Creature",
      "A creature: a built-in name ('hexapod', 'wedge') or a JSON file; None: the default. "
      "damage: as --damage, e.g. 'right_front:weak=0.2,left_rear:locked'")
      .def(py::init(&MakeCreature), py::arg("path") = py::none(), py::arg("damage") = "")
      .def_property_readonly("damage", [](const PyCreature& c) { return c.model->damage; })
      .def_property_readonly("name", [](const PyCreature& c) { return CreatureLabel(c.spec); })
      .def_property_readonly("particles",
                             [](const PyCreature& c) { return c.model->num_particles(); })
      .def_property_readonly("springs", [](const PyCreature& c) { return c.model->num_springs(); })
      .def_property_readonly("legs",
                             [](const PyCreature& c) {
                               std::vector<std::string> names;
                               for (const Leg& leg : c.model->legs) names.push_back(leg.name);
                               return names;
                             })
      .def("__repr__", [](const PyCreature& c) {
        const std::string damage =
            c.model->damage.empty() ? "" : ", damage='" + c.model->damage + "'";
        return "hexgait.Creature('" + CreatureLabel(c.spec) + "'" + damage + ")";
      });
  m.attr("builtin_creatures") = BuiltInCreatureNames();

  py::class_<PyMotorProgram>(m, "MotorProgram",
                             "A motor program file; None: the creature's built-in program")
      .def(py::init([](const std::optional<std::string>& path, const py::handle& creature) {
             return MakeMotorProgram(path, CreatureArg(creature));
           }),
           py::arg("path") = py::none(), py::arg("creature") = py::none())
      .def_property_readonly("cycle_period",
                             [](const PyMotorProgram& p) { return p.program->cycle_period; })
      .def_property_readonly("gene_length_step",
                             [](const PyMotorProgram& p) { return p.program->gene_length_step; })
      .def("__repr__", [](const PyMotorProgram& p) {
        return "hexgait.MotorProgram(" +
               (p.path.empty() ? std::string("built-in") : "'" + p.path + "'") + ")";
      });

  py::class_<PyEvaluator>(
      m, "Evaluator",
      "Runs populations of genomes or offsets on every thread; the same bits as "
      "the command line, whatever the batch size or thread count")
      .def(py::init<const py::handle&, const py::handle&, double, double, const std::string&,
                    const std::string&, int, bool, int, bool, bool>(),
           py::arg("creature") = py::none(), py::arg("motor") = py::none(),
           py::arg("time") = kPaperDuration, py::arg("dt") = kPaperTimeStep,
           py::arg("integrator") = "euler", py::arg("precision") = "double", py::arg("threads") = 0,
           py::arg("symmetric") = false, py::arg("batch_lanes") = 0, py::arg("allow_long") = false,
           py::arg("stop_at_fall") = false)
      .def("evaluate", &PyEvaluator::Evaluate, py::arg("genomes"),
           "genomes: (n, genes) integers in [-8, 7]. Returns a dict of arrays (distance, fell, "
           "fall_time, fall_cycle, diverged, ...)")
      .def("evaluate_offsets", &PyEvaluator::EvaluateOffsets, py::arg("offsets"),
           "offsets: (n, genes) rest-length offsets in length units (gene * gene_length_step "
           "gives evaluate's result)")
      .def_property_readonly("genes", &PyEvaluator::genes)
      .def_property_readonly("gene_length_step", &PyEvaluator::gene_length_step)
      .def_property_readonly("gene_names", &PyEvaluator::gene_names)
      .def("__repr__",
           [](const PyEvaluator& e) { return "hexgait.Evaluator(" + e.Describe() + ")"; });

  py::class_<PyRunResults>(m, "RunResults",
                           "Every field of evaluate()'s results, exactly: what Search.tell takes")
      .def("__len__", [](const PyRunResults& r) { return r.results.size(); });

  py::class_<PySearch>(
      m, "Search",
      "An optimizer driven by ask() and tell(): 'ga' (the paper's), 'cmaes' or 'map-elites', "
      "on an Evaluator's creature and run settings. The same seed and settings give the same "
      "bits as `hexgait evolve` / `hexgait repertoire`")
      .def(py::init<const std::string&, const PyEvaluator&, uint64_t, std::optional<int>, int,
                    double, double, double, double, int, long long, int, const std::string&, int,
                    bool>(),
           py::arg("algorithm"), py::arg("evaluator"), py::arg("seed") = 1,
           py::arg("population") = py::none(), py::arg("generations") = 10, py::arg("sigma") = 2.0,
           py::arg("crossover_rate") = 0.7, py::arg("mutation_rate") = 0.01,
           py::arg("initial_mutation_rate") = 0.02, py::arg("elites") = 1,
           py::arg("evaluations") = 100000, py::arg("batch") = 500, py::arg("descriptor") = "duty",
           py::arg("bins") = 5, py::arg("confirm_in_double") = false)
      .def("ask", &PySearch::Ask,
           "The next batch: an (n, genes) array of rest-length offsets for "
           "Evaluator.evaluate_offsets")
      .def("tell", &PySearch::Tell, py::arg("results"),
           "The dict evaluate_offsets returned for the last ask()")
      .def_property_readonly("done", &PySearch::done)
      .def_property_readonly("evaluations", &PySearch::evaluations)
      .def_property_readonly("budget", &PySearch::budget)
      .def("save", &PySearch::Save, "The state as the checkpoint text the command writes")
      .def("best", &PySearch::Best, "The best individual so far (offsets, genes, result)")
      .def("history", &PySearch::History)
      .def("archive", &PySearch::ArchiveList, "MAP-Elites: the elites of the archive")
      .def("__repr__", [](const PySearch& s) { return "hexgait.Search(" + s.Describe() + ")"; });

  m.def("load_genome", &LoadGenome, py::arg("path"), py::arg("creature") = py::none(),
        py::arg("motor") = py::none(),
        "A genome file (as evolve writes best.genome) as an int8 array of genes, or, for a "
        "continuous genome (evolve --algorithm cmaes), a float64 array of offsets");
  m.def("save_genome", &SaveGenome, py::arg("path"), py::arg("genome"),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(), py::arg("comment") = "",
        "Writes a genome file that evolve, simulate and render read");
  m.def("simulate", &SimulateRun, py::arg("genome") = py::none(), py::arg("creature") = py::none(),
        py::arg("motor") = py::none(), py::arg("time") = kPaperDuration,
        py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler", py::arg("interval") = 0.1,
        py::arg("positions_at") = py::none(), py::arg("allow_long") = false,
        "One run as `hexgait simulate`: the result, the trace (time, centre, lowest_body, "
        "tilt_degrees, feet_on_ground) every `interval`, and the particles' positions at "
        "`positions_at` times");
  m.def("render_still", &RenderStillFrame, py::kw_only(), py::arg("genome") = py::none(),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        py::arg("unoptimized") = false, py::arg("time") = 0.0, py::arg("size") = "1280x720",
        py::arg("view") = py::none(), py::arg("camera") = py::none(), py::arg("track") = py::none(),
        py::arg("cues") = py::none(), py::arg("no_overlay") = false, py::arg("no_shadow") = false,
        py::arg("msaa") = 0, py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false, py::arg("gl") = py::none(),
        "An (H, W, 3) uint8 frame, as `hexgait still` draws it: genome= an array or a path "
        "(None: the unoptimised program), time= (0: the rest pose, the paper's Figure 1), size= "
        "'WxH', view=, camera=, track=, cues= (a string or a list), no_overlay=, no_shadow=, "
        "msaa=, dt=, integrator=, gl=");
  m.def("adapt", &AdaptToDamageDict, py::arg("repertoire"), py::kw_only(), py::arg("damage"),
        py::arg("trials") = 20, py::arg("stop") = 0.9, py::arg("kappa") = 0.05,
        py::arg("length_scale") = 0.4, py::arg("signal_variance") = 1.0, py::arg("noise") = 0.001,
        py::arg("seed") = 1, py::arg("threads") = 0, py::arg("creature") = py::none(),
        py::arg("motor") = py::none(),
        "Intelligent Trial and Error, as `hexgait adapt` runs it (no files written): a dict "
        "with the trials (elite, cell, predicted_mean, predicted_std, distance, best, fell, "
        "diverged), why it stopped, the adapted elite and distance, the intact best and the best "
        "elite on the damaged creature (every elite run once, for comparison), the best of as "
        "many random elites, and every elite's intact and damaged distance, and whether it fell "
        "or diverged damaged (NumPy arrays). creature and motor: the repertoire's, as "
        "--creature and --motor (None: the creature it recorded)");
  m.def("replay_html", &ReplayPageText, py::kw_only(), py::arg("genome") = py::none(),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        py::arg("unoptimized") = false, py::arg("time") = kPaperDuration,
        py::arg("view") = py::none(), py::arg("camera") = py::none(), py::arg("track") = py::none(),
        py::arg("cues") = py::none(), py::arg("no_overlay") = false, py::arg("no_shadow") = false,
        py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false,
        "The self-contained HTML page `hexgait replay` writes, as a string (in Jupyter: "
        "IPython.display.HTML(page)): genome= an array or a path (None: the unoptimised "
        "program), time=, view=, camera=, track=, cues= (what the page opens with), "
        "no_overlay=, no_shadow=, dt=, integrator=. A run too long for a page is decimated with "
        "a UserWarning, or refused");
  m.def("render_movie", &RenderMovieFile, py::arg("path"), py::kw_only(),
        py::arg("genome") = py::none(), py::arg("creature") = py::none(),
        py::arg("motor") = py::none(), py::arg("unoptimized") = false,
        py::arg("time") = kPaperDuration, py::arg("size") = "1280x720", py::arg("fps") = 30,
        py::arg("speed") = 0.0, py::arg("msaa") = 0, py::arg("preset") = "veryfast",
        py::arg("crf") = 20, py::arg("overlay") = false, py::arg("no_shadow") = false,
        py::arg("no_caption") = false, py::arg("view") = py::none(), py::arg("camera") = py::none(),
        py::arg("track") = py::none(), py::arg("cues") = py::none(), py::arg("frames") = py::none(),
        py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false, py::arg("gl") = py::none(),
        "Writes an MP4 of one run, as `hexgait render --out path` does, and returns the path: "
        "genome=, time=, size=, fps=, speed= (0: a gait cycle per second), msaa=, preset=, crf=, "
        "overlay=, no_shadow=, no_caption=, view=, camera=, track=, cues=, frames= (a folder for "
        "PNGs), dt=, integrator=, gl=");

  py::class_<GaussianProcess>(
      m, "GaussianProcess",
      "Gaussian-process regression with a fixed Matern 5/2 kernel, as Intelligent Trial and "
      "Error uses over behaviour descriptors (adapt/gaussian_process.h): length_scale, "
      "signal_variance (sigma^2) and noise (observation variance) default to the ITE code's 0.4, "
      "1 and 0.001")
      .def(py::init([](double length_scale, double signal_variance, double noise) {
             return GaussianProcess({length_scale, signal_variance, noise});
           }),
           py::arg("length_scale") = 0.4, py::arg("signal_variance") = 1.0,
           py::arg("noise") = 0.001)
      .def(
          "fit",
          [](GaussianProcess& gp, const Eigen::MatrixXd& x, const Eigen::VectorXd& y,
             const std::optional<Eigen::VectorXd>& prior) {
            gp.Fit(x, y, PriorOrZero(prior, x.rows()));
          },
          py::arg("x"), py::arg("y"), py::arg("prior_mean") = py::none(),
          "Conditions on the rows of x (n, d) with values y (n,) and the prior mean at each "
          "(n,; None: 0)")
      .def(
          "predict",
          [](const GaussianProcess& gp, const Eigen::MatrixXd& x,
             const std::optional<Eigen::VectorXd>& prior) {
            const Eigen::VectorXd priors = PriorOrZero(prior, x.rows());
            if (priors.size() != x.rows()) throw InputError("predict: one prior mean per row of x");
            Eigen::VectorXd mean(x.rows()), sd(x.rows());
            for (Eigen::Index i = 0; i < x.rows(); ++i) {
              const GaussianPrediction p = gp.Predict(x.row(i).transpose(), priors[i]);
              mean[i] = p.mean;
              sd[i] = std::sqrt(p.variance);
            }
            return py::make_tuple(mean, sd);
          },
          py::arg("x"), py::arg("prior_mean") = py::none(),
          "The posterior mean and standard deviation (of the latent function, without the "
          "noise) at the rows of x, given the prior mean at each (None: 0)")
      .def_property_readonly("observations", &GaussianProcess::num_observations);
}
