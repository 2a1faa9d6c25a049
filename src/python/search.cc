// hexgait.Search: the commands' optimizers (search/optimizer.h) driven by ask() and tell().
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ga/archive_table.h"
#include "ga/behaviour.h"
#include "ga/map_elites.h"
#include "motor/assets.h"
#include "python/arguments.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/evaluator.h"
#include "python/interrupts.h"
#include "run/repertoire_run.h"
#include "search/archive_optimizer.h"
#include "search/ga_optimizer.h"
#include "search/generational.h"
#include "search/search_driver.h"
#include "util/error.h"

namespace hexgait::python {
namespace {

// "map-elites, cma-mae".
std::string ArchiveNames() {
  std::string names;
  for (const ArchiveOptimizerKind* kind : ArchiveOptimizerKinds()) {
    names += (names.empty() ? "" : ", ") + std::string(kind->name);
  }
  return names;
}

// The class's docstring, from the registries and the archive optimizers' tables, so a
// parameter added to a table is documented here without another line.
std::string SearchDoc() {
  std::string doc =
      "Search(algorithm, evaluator, **parameters): an optimizer driven by ask() and tell() on an "
      "Evaluator's creature and run settings. The same seed and settings give the same bits as "
      "`hexgait evolve` / `hexgait repertoire`.\n\n";
  const auto table = [&](const ParamTable& params) {
    for (const ParamSpec& spec : params) {
      doc += std::string(", ") + spec.name + "=" + ParamText(spec.value) + " (" + spec.help + ")";
    }
    doc += ".\n";
  };
  for (const OptimizerKind* kind : OptimizerKinds()) {
    doc += std::string("'") + kind->name + "': " + kind->summary +
           ". Keywords: seed=1, population=" + std::to_string(kind->default_population) +
           ", generations=10";
    table(*kind->params);
  }
  for (const ArchiveOptimizerKind* kind : ArchiveOptimizerKinds()) {
    doc += std::string("'") + kind->name + "': " + kind->summary +
           ". Keywords: seed=1, evaluations=100000, batch=500, descriptor='duty', bins=5, "
           "confirm_in_double=False";
    table(*kind->params);
  }
  return doc;
}

// Keyword arguments, each taken once by name; what is left over is refused by name.
class Keywords {
 public:
  Keywords(const std::string& algorithm, const py::kwargs& keywords) : algorithm_(algorithm) {
    for (const auto& [key, value] : keywords) left_[key.cast<std::string>()] = value;
  }
  template <class T>
  T Take(const char* name, T fallback) {
    const auto it = left_.find(name);
    if (it == left_.end()) return fallback;
    T value = it->second.cast<T>();
    left_.erase(it);
    return value;
  }
  // The given values of `table`'s parameters.
  ParamValues TakeTable(const ParamTable& table) {
    ParamValues given;
    for (const ParamSpec& spec : table) {
      if (left_.count(spec.name)) given.Set(spec.name, Take<double>(spec.name, 0), spec.integer);
    }
    return given;
  }
  void RefuseTheRest() const {
    if (left_.empty()) return;
    throw py::type_error("Search('" + algorithm_ + "') takes no keyword '" + left_.begin()->first +
                         "' (help(hexgait.Search) lists each algorithm's)");
  }

 private:
  std::string algorithm_;
  std::map<std::string, py::handle> left_;
};

// hexgait.Search: an optimizer of the search driver (search/optimizer.h) on an Evaluator's
// creature, program and run settings, driven from Python by ask() and tell(). The same
// optimizer objects the commands run, so the same seed and settings give the same bits.
class PySearch {
 public:
  PySearch(const std::string& algorithm, const PyEvaluator& evaluator, const py::kwargs& kwargs)
      : model_(evaluator.creature().model),
        program_(evaluator.motor().program),
        legs_(static_cast<int>(model_->legs.size())),
        algorithm_(algorithm) {
    const EvaluatorConfig& config = evaluator.config();
    config_ = config;
    decoder_ = std::make_unique<CandidateDecoder>(*model_, *program_, evaluator.layout());
    const bool symmetric = evaluator.layout()->symmetric;
    const SearchScene scene{*model_, *program_, CreatureLabel(evaluator.creature().spec)};
    Keywords keywords(algorithm, kwargs);
    if (const ArchiveOptimizerKind* kind = ArchiveOptimizerKindOrNull(algorithm)) {
      MapElitesParams p;
      p.algorithm = kind->name;
      p.seed = keywords.Take<uint64_t>("seed", p.seed);
      p.evaluations = keywords.Take<long long>("evaluations", p.evaluations);
      p.batch = keywords.Take<int>("batch", p.batch);
      p.descriptor = keywords.Take<std::string>("descriptor", p.descriptor);
      p.bins = keywords.Take<int>("bins", p.bins);
      p.confirm_in_double = keywords.Take<bool>("confirm_in_double", false);
      p.settings = keywords.TakeTable(*kind->params);
      keywords.RefuseTheRest();
      p.symmetric = symmetric;
      p.precision = config.precision;
      p.run = config.run;
      archive_ = MakeArchiveOptimizer(scene, StartArchiveSearch(p, *model_));
      optimizer_ = archive_.get();
      if (p.confirm_in_double) {  // as `hexgait repertoire`: a double evaluator of the same run
        in_double_ = MakeDoubleEvaluator(*model_, *program_, p);
        archive_->ConfirmWith(*in_double_);
      }
      return;
    }
    const OptimizerKind& kind = FindOptimizerKindOfAny(algorithm);
    EvolutionParams p;
    p.seed = keywords.Take<uint64_t>("seed", p.seed);
    p.population = keywords.Take<int>("population", kind.default_population);
    p.generations = keywords.Take<int>("generations", p.generations);
    p.settings = ParamValues::Defaults(*kind.params, keywords.TakeTable(*kind.params));
    keywords.RefuseTheRest();
    p.symmetric = symmetric;
    p.precision = config.precision;
    p.run = config.run;
    generational_ = kind.start(scene, p);
    optimizer_ = generational_.get();
  }

  py::array_t<double> Ask() {
    if (optimizer_->Done()) throw InputError("ask: the search is done (its budget is spent)");
    const Candidates& c = optimizer_->Ask();
    asked_ = EvaluationFingerprint(*model_, *program_, config_.run, config_.precision,
                                   decoder_->Decode(c));
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
    const PyRunResults& told_results = results["results"].cast<const PyRunResults&>();
    // (A wrong number of results is the optimizer's to name.)
    if (asked_ && told_results.results.size() == optimizer_->Ask().size() &&
        told_results.fingerprint != *asked_) {
      throw InputError(
          "tell: these results are not the last ask's candidates evaluated with this search's "
          "creature, motor program and run settings");
    }
    const std::vector<RunResult>& told = told_results.results;
    Interruptible([&] { optimizer_->Tell(told); }, /*keep_gil=*/true);
    asked_.reset();
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
    } else if (archive_ && archive_->state().archive.Best()) {
      genome = &archive_->state().archive.Best()->genome;
      result = &archive_->state().archive.Best()->result;
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

  // One dict per generation (best, mean, worst) or per archive batch (filled, qd_score, best).
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
      for (const ArchiveStats& a : archive_->state().history) {
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

  // An archive search's elites: one dict per filled cell, in the order cells were first filled.
  py::list ArchiveList() const {
    if (!archive_)
      throw InputError("archive: only an archive search (" + ArchiveNames() + ") has one");
    py::list out;
    const Archive& archive = archive_->state().archive;
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
  std::unique_ptr<Evaluator> in_double_;  // confirms an archive's admissions: outlives archive_
  std::unique_ptr<ArchiveOptimizer> archive_;
  Optimizer* optimizer_ = nullptr;
  EvaluatorConfig config_;
  std::unique_ptr<CandidateDecoder> decoder_;
  std::optional<uint64_t> asked_;  // the fingerprint of the results the last ask awaits
};

// A finished repertoire's archive as a pandas DataFrame in pyribs' layout (ga/archive_table.h:
// the columns of archive.csv, integers as int64).
py::object LoadArchive(const std::string& path) {
  py::module_ pandas;
  try {
    pandas = py::module_::import("pandas");
  } catch (const py::error_already_set&) {
    throw py::import_error("load_archive needs pandas (Debian: python3-pandas)");
  }
  const LoadedRepertoire repertoire = LoadRepertoire(path, SceneOptions(), "path");
  const MapElitesState& state = repertoire.state;
  const std::vector<ArchiveColumn> table =
      ArchiveTable(repertoire.scene.model, FindBehaviourDescriptor(state.params.descriptor),
                   state.archive, repertoire.scene.program.gene_length_step);
  py::dict columns;
  py::list order;
  for (const ArchiveColumn& c : table) {
    if (c.integer) {
      columns[py::str(c.name)] = py::array_t<int64_t>(
          static_cast<py::ssize_t>(c.ints.size()), reinterpret_cast<const int64_t*>(c.ints.data()));
    } else {
      columns[py::str(c.name)] =
          py::array_t<double>(static_cast<py::ssize_t>(c.reals.size()), c.reals.data());
    }
    order.append(c.name);
  }
  return pandas.attr("DataFrame")(columns, py::arg("columns") = order);
}

// `hexgait repertoire --out DIR --no-movie`: a map of gaits written to `out`, by the same call.
py::dict MakeRepertoire(const std::string& out, long long evaluations, int batch, double time,
                        uint64_t seed, int bins, const std::string& precision, int threads,
                        const std::string& algorithm, const py::handle& creature_arg,
                        const py::handle& motor_arg) {
  if (out.empty()) throw InputError("out: empty value");
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  RepertoireSettings settings;
  settings.scene = SceneFor(creature, motor, kPaperTimeStep, "euler", false);
  settings.params.evaluations = evaluations;
  settings.params.batch = batch;
  settings.params.seed = seed;
  settings.params.bins = bins;
  settings.params.threads = threads;
  settings.params.algorithm = algorithm;
  settings.time = time;
  settings.precision = precision;
  settings.no_movie = true;
  settings.out_dir = out;
  RepertoireObserver observer;
  observer.progress = CheckPythonSignalsBetween;
  const RepertoireOutcome outcome =
      Interruptible([&] { return RunRepertoire(settings, observer); });
  py::dict result;
  result["dir"] = outcome.dir;
  result["tables"] = outcome.tables;
  result["seconds"] = outcome.seconds;
  return result;
}

}  // namespace

void BindSearch(py::module_& m) {
  m.def("repertoire", &MakeRepertoire, py::arg("out"), py::kw_only(),
        py::arg("evaluations") = 20000, py::arg("batch") = 500, py::arg("time") = kPaperDuration,
        py::arg("seed") = 1, py::arg("bins") = 5, py::arg("precision") = "auto",
        py::arg("threads") = 0, py::arg("algorithm") = "map-elites",
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        "Fills a map of gaits into the folder `out`, as `hexgait repertoire --out out --no-movie` "
        "does (archive.json, archive.csv, map.png, progress.png, table.md), by the same library "
        "call; returns its folder, tables and seconds. load_archive(out) reads it back, "
        "adapt(out, damage=...) adapts from it");
  m.def("load_archive", &LoadArchive, py::arg("path"),
        "A finished repertoire (hexgait repertoire --out DIR) as a pandas DataFrame in pyribs' "
        "ArchiveDataFrame layout, one row per elite: index, objective (distance), measures_0.. "
        "(the behaviour descriptor), solution_0.. (genes), then bin_LEG, found_at and "
        "mean_feet_on_ground; the same table as DIR/archive.csv, read from the checked archive");
  static const std::string doc = SearchDoc();
  py::class_<PySearch>(m, "Search", doc.c_str())
      .def(py::init<const std::string&, const PyEvaluator&, const py::kwargs&>(),
           py::arg("algorithm"), py::arg("evaluator"))
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
      .def("archive", &PySearch::ArchiveList, "An archive search's elites")
      .def("__repr__", [](const PySearch& s) { return "hexgait.Search(" + s.Describe() + ")"; });
}

}  // namespace hexgait::python
