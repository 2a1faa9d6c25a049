#include "python/evaluator.h"

#include <algorithm>
#include <cstdio>

#include "ga/genome_io.h"
#include "motor/assets.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/interrupts.h"
#include "run/io_paths.h"
#include "run/simulate_run.h"
#include "run/work_size.h"
#include "search/search_driver.h"
#include "sim/evaluate.h"
#include "sim/trace.h"
#include "simd/isa.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait::python {

PyEvaluator::PyEvaluator(const py::handle& creature, const py::handle& motor, double time,
                         double dt, const std::string& integrator, const std::string& precision,
                         int threads, bool symmetric, int batch_lanes, bool allow_long,
                         bool stop_at_fall)
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

py::dict PyEvaluator::Evaluate(const py::handle& genomes) {
  int rows = 0;
  const std::vector<int8_t> genes = GenesFromArray(genomes, layout_->num_genes(), "genomes", &rows);
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

py::dict PyEvaluator::EvaluateOffsets(const py::handle& offsets) {
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

std::vector<std::pair<std::string, std::string>> PyEvaluator::gene_names() const {
  std::vector<std::pair<std::string, std::string>> names;
  for (int g = 0; g < layout_->num_genes(); ++g) {
    names.emplace_back(layout_->spring_name[g], layout_->position_name[g]);
  }
  return names;
}

// The population in slices of about a quarter of a second each (EvaluateInSlices), the GIL
// released while they run: between slices a Ctrl-C raises KeyboardInterrupt (Python's handler
// runs only when the GIL is held).
py::dict PyEvaluator::Run(const std::vector<RestLengthTable>& tables) {
  RefuseLongBatch(tables.size());
  std::vector<RunResult> results;
  results = Interruptible([&] {
    std::lock_guard<std::mutex> lock(mutex_);
    return EvaluateInSlices(*evaluator_, tables, config_.threads, 0.25, CheckPythonSignalsBetween);
  });
  py::dict out = ResultsToDict(results, static_cast<int>(creature_.model->legs.size()));
  // Every field of every result, exactly, for Search.tell.
  out["results"] = py::cast(PyRunResults{
      std::move(results), EvaluationFingerprint(*creature_.model, *motor_.program, config_.run,
                                                config_.precision, tables)});
  return out;
}

// The commands' over-an-hour rule (run/work_size.h) for a whole population.
void PyEvaluator::RefuseLongBatch(size_t creatures) const {
  RefuseLongEvaluations(std::to_string(creatures) + " creatures", *creature_.model,
                        static_cast<double>(creatures), config_.run,
                        ResolveThreadCount(config_.threads), allow_long_);
}

namespace {

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
  // As on the command line: the output is never one of the files the call reads.
  IoPaths paths;
  if (!IsBuiltInCreature(creature.spec)) paths.Input("creature", creature.spec);
  paths.Input("motor", motor.path);
  paths.Output("path", path);
  paths.Check();
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
    return SimulateGenome(scene, genome, run, request, "interval", CheckPythonSignalsBetween);
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

}  // namespace

void BindEvaluator(py::module_& m) {
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
      .def_property_readonly(
          "time", [](const PyEvaluator& e) { return e.config().run.duration; },
          "The time units each run lasts (a fall may end it sooner with stop_at_fall)")
      .def("__repr__",
           [](const PyEvaluator& e) { return "hexgait.Evaluator(" + e.Describe() + ")"; });

  py::class_<PyRunResults>(m, "RunResults",
                           "Every field of evaluate()'s results, exactly: what Search.tell takes")
      .def("__len__", [](const PyRunResults& r) { return r.results.size(); });

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
}

}  // namespace hexgait::python
