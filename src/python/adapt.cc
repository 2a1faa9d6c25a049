// hexgait.adapt (Intelligent Trial and Error, as `hexgait adapt` runs it) and
// hexgait.GaussianProcess, the model it uses.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "adapt/gaussian_process.h"
#include "model/damage.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "python/interrupts.h"
#include "run/adapt_run.h"
#include "util/error.h"

namespace hexgait::python {
namespace {

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

// One trial as both adapt() and trial_and_error() give it.
py::dict TrialDict(const Trial& t, const std::string& prior) {
  py::dict d;
  d["elite"] = t.elite;
  d["prior"] = prior;
  d["predicted_mean"] = t.predicted_mean;
  d["predicted_std"] = t.predicted_std;
  d["distance"] = t.distance;
  d["best"] = t.best;
  d["best_elite"] = t.best_elite;
  return d;
}

// library=None: none; True: the command's --library; a list: those injuries on every leg.
std::vector<std::string> LibraryKinds(const py::handle& library) {
  if (library.is_none()) return {};
  if (py::isinstance<py::bool_>(library)) {
    return library.cast<bool>() ? DefaultDamageLibraryKinds() : std::vector<std::string>{};
  }
  if (py::isinstance<py::str>(library)) {
    throw py::type_error("library must be None, True or a list of injuries like ['weak=0.2']");
  }
  return library.cast<std::vector<std::string>>();
}

// stop=None: no stop rule, every trial run (the command's --no-stop).
void SetStop(std::optional<double> stop, TrialAndErrorParams* params) {
  params->stop_rule = stop.has_value();
  if (stop) params->stop_fraction = *stop;
}

py::dict AdaptToDamageDict(const std::string& repertoire, const std::string& damage, int trials,
                           std::optional<double> stop, const std::string& normalise, double kappa,
                           double length_scale, double signal_variance, double noise, uint64_t seed,
                           int threads, const py::handle& library, const py::handle& creature,
                           const py::handle& motor) {
  AdaptRequest request;
  request.library_kinds = LibraryKinds(library);
  request.repertoire_dir = repertoire;
  request.creature_path = AdaptCreatureSpec(creature);
  request.motor_path = AdaptMotorPath(motor);
  request.damage = damage;
  request.params.max_trials = trials;
  SetStop(stop, &request.params);
  request.params.normalise = ParseNormalisation(normalise);
  request.params.kappa = kappa;
  request.params.gp.length_scale = length_scale;
  request.params.gp.signal_variance = signal_variance;
  request.params.gp.noise = noise;
  request.seed = seed;
  request.threads = threads;
  // Between pieces of a fraction of a second each, a Ctrl-C raises KeyboardInterrupt.
  request.on_progress = CheckPythonSignalsBetween;
  const AdaptOutcome o = Interruptible([&] { return AdaptToDamage(request); });
  py::list trial_list;
  for (const Trial& t : o.adaptation.trials) {
    py::dict d = TrialDict(t, o.PriorName(t.prior));
    d["cell"] = o.cells[static_cast<size_t>(t.elite)];
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
  out["library"] = o.library;
  out["library_runs"] = o.library_runs;
  out["trials"] = trial_list;
  out["stopped"] = TrialStopText(o.adaptation.stop);
  out["stop_rule_trials"] = o.adaptation.stop_rule_trials;
  out["adapted"] = o.adapted;
  out["adapted_distance"] = o.adaptation.trials.back().best;
  out["intact_best"] = o.intact_best;
  out["damaged_best"] = o.damaged_best;
  out["random_best"] = o.random_best;
  out["ga_best"] = o.ga_best;
  out["ga_evaluations"] = o.ga_evaluations;
  // As adapt.json's at_stop_rule: with stop=None, the result and comparisons where the rule
  // held (None where it never did, or when the rule was on).
  out["at_stop_rule"] = py::none();
  if (o.at_stop_rule) {
    py::dict at;
    at["trials"] = o.at_stop_rule->trials;
    at["adapted_distance"] = o.at_stop_rule->adapted;
    at["random_best"] = o.at_stop_rule->random_best;
    at["ga_best"] = o.at_stop_rule->ga_best;
    at["ga_evaluations"] = o.at_stop_rule->ga_evaluations;
    out["at_stop_rule"] = at;
  }
  out["cells"] = Float64Array(std::vector<double>(o.cells.begin(), o.cells.end()));
  out["intact_distance"] = Float64Array(o.prior);
  out["damaged_distance"] = Float64Array(damaged);
  out["damaged_fell"] = fell;
  out["damaged_diverged"] = diverged;
  return out;
}

// The prior means for `n` points: None is zero at every point (a plain GP on the values).
Eigen::VectorXd PriorOrZero(const std::optional<Eigen::VectorXd>& prior, Eigen::Index n) {
  return prior ? *prior : Eigen::VectorXd(Eigen::VectorXd::Zero(n));
}

// Intelligent Trial and Error's loop alone, on elites given as arrays: `trial` is a callable
// (elite index -> distance, or (distance, descriptor) with a library) or the distance of every
// elite on the damaged creature (a trial of elite i is then element i, and with a library its
// descriptor row i of `shown`, as a deterministic simulation would give). `library`: {damage:
// (distances (n,), descriptors (n, d))} in the order given. For studies of the loop's settings
// over many damages without running every elite for each setting.
py::dict TrialAndErrorDict(const Eigen::MatrixXd& descriptors, const Eigen::VectorXd& prior,
                           const py::object& trial, int trials, std::optional<double> stop,
                           const std::string& normalise, double kappa, double length_scale,
                           double signal_variance, double noise, const py::dict& library,
                           const std::optional<Eigen::MatrixXd>& shown) {
  if (prior.size() != descriptors.rows()) {
    throw InputError("trial_and_error: one prior distance per row of descriptors");
  }
  std::vector<ArchiveElite> archive;
  for (Eigen::Index i = 0; i < descriptors.rows(); ++i) {
    archive.push_back({descriptors.row(i).transpose(), prior[i]});
  }
  std::vector<DamageLibraryMember> members;
  for (const auto& [name, tables] : library) {
    const auto pair = tables.cast<std::pair<Eigen::VectorXd, Eigen::MatrixXd>>();
    members.push_back({name.cast<std::string>(), pair.first, pair.second});
  }
  TrialAndErrorParams params;
  params.max_trials = trials;
  SetStop(stop, &params);
  params.normalise = ParseNormalisation(normalise);
  params.kappa = kappa;
  params.gp = {length_scale, signal_variance, noise};
  RunTrial run_trial;
  Eigen::VectorXd known;
  if (PyCallable_Check(trial.ptr())) {
    run_trial = [&trial](int index) -> TrialMeasure {
      const py::object measured = trial(index);
      if (py::isinstance<py::tuple>(measured)) {
        const auto pair = measured.cast<std::pair<double, Eigen::VectorXd>>();
        return {pair.first, pair.second};
      }
      return measured.cast<double>();
    };
  } else {
    known = trial.cast<Eigen::VectorXd>();
    if (known.size() != descriptors.rows()) {
      throw InputError("trial_and_error: one damaged distance per row of descriptors");
    }
    if (shown && (shown->rows() != descriptors.rows() || shown->cols() != descriptors.cols())) {
      throw InputError("trial_and_error: shown must have the shape of descriptors");
    }
    run_trial = [&known, &shown](int index) -> TrialMeasure {
      if (!shown) return known[index];
      return {known[index], shown->row(index).transpose()};
    };
  }
  LibraryRuns runs(std::move(members), static_cast<int>(descriptors.rows()),
                   static_cast<int>(descriptors.cols()));
  const TrialAndErrorResult result = RunTrialAndError(archive, run_trial, params, runs);
  py::list trial_list;
  for (const Trial& t : result.trials) {
    trial_list.append(
        TrialDict(t, t.prior < 0 ? kIntactPriorName : runs.names()[static_cast<size_t>(t.prior)]));
  }
  py::dict out;
  // The library's runs the loop read: what `hexgait adapt --library` would have simulated.
  out["library_runs"] = runs.runs_made();
  out["trials"] = trial_list;
  out["stopped"] = TrialStopText(result.stop);
  out["stop_rule_trials"] = result.stop_rule_trials;
  out["max_predicted_mean"] = result.max_predicted_mean;
  return out;
}

}  // namespace

void BindAdapt(py::module_& m) {
  // The injuries adapt(library=True) and `hexgait adapt --library` simulate on every leg.
  m.attr("damage_library_kinds") = DefaultDamageLibraryKinds();
  // The keywords' defaults are the library's (the command's too).
  const TrialAndErrorParams d;
  m.def("adapt", &AdaptToDamageDict, py::arg("repertoire"), py::kw_only(), py::arg("damage"),
        py::arg("trials") = d.max_trials, py::arg("stop") = d.stop_fraction,
        py::arg("normalise") = NormalisationName(d.normalise), py::arg("kappa") = d.kappa,
        py::arg("length_scale") = d.gp.length_scale,
        py::arg("signal_variance") = d.gp.signal_variance, py::arg("noise") = d.gp.noise,
        py::arg("seed") = 1, py::arg("threads") = 0, py::arg("library") = py::none(),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        "Intelligent Trial and Error, as `hexgait adapt` runs it (no files written): a dict "
        "with the trials (elite, cell, predicted_mean, predicted_std, distance, best, fell, "
        "diverged), why it stopped (stop=None: no stop rule, every trial run; stop_rule_trials: "
        "where the rule held, 0 never), the adapted elite "
        "and distance, the intact best and the best "
        "elite on the damaged creature (every elite run once, for comparison), the best of as "
        "many random elites, and every elite's intact and damaged distance, and whether it fell "
        "or diverged damaged (NumPy arrays). library: None, True (the command's --library) or "
        "a list of injuries like ['weak=0.2'] simulated on every leg before the trials, each "
        "trial's prior then named in its 'prior' (library_runs: the elites' runs on the "
        "library's creatures it made). creature and motor: the repertoire's, as "
        "--creature and --motor (None: the creature it recorded)");
  m.def("trial_and_error", &TrialAndErrorDict, py::arg("descriptors"), py::arg("prior"),
        py::arg("trial"), py::kw_only(), py::arg("trials") = d.max_trials,
        py::arg("stop") = d.stop_fraction, py::arg("normalise") = NormalisationName(d.normalise),
        py::arg("kappa") = d.kappa, py::arg("length_scale") = d.gp.length_scale,
        py::arg("signal_variance") = d.gp.signal_variance, py::arg("noise") = d.gp.noise,
        py::arg("library") = py::dict(), py::arg("shown") = py::none(),
        "Intelligent Trial and Error's loop alone (adapt/trial_and_error.h), as adapt() runs "
        "it: elites' descriptors (n, d) and recorded distances (n,), and trial, a callable "
        "(elite index -> distance on the damaged creature) or every elite's damaged distance "
        "(n,). library: {damage: (distances (n,), descriptors (n, d))}, simulated damages the "
        "prior is chosen from by the descriptors the trials showed: then trial returns "
        "(distance, descriptor), or shown (n, d) holds every elite's damaged descriptor. A dict: "
        "the trials (elite, prior, predicted_mean, predicted_std, distance, best, best_elite), "
        "why it stopped (stop=None: every trial run; stop_rule_trials: where the rule held, 0 "
        "never), the largest posterior mean after the last trial, and library_runs: how many of "
        "the library's runs the loop read (what adapt() simulates of it)");
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

}  // namespace hexgait::python
