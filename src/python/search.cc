// hexgait.Search: the commands' optimizers (search/optimizer.h) driven by ask() and tell().
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ga/map_elites.h"
#include "motor/assets.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/evaluator.h"
#include "python/interrupts.h"
#include "search/ga_optimizer.h"
#include "search/generational.h"
#include "search/map_elites_optimizer.h"
#include "util/error.h"

namespace hexgait::python {
namespace {

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

}  // namespace

void BindSearch(py::module_& m) {
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
}

}  // namespace hexgait::python
