#include "bench/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bench/free_flight.h"
#include "ga/evolution.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "sim/step_loop.h"
#include "sim/steppers.h"

namespace hexgait {
namespace {

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// Largest finite total energy seen, sampled every `every` steps.
struct EnergyObserver {
  const CreatureModel& model;
  int every = 40;
  int until = 40;
  double max_energy = -INFINITY;
  void OnStep(const SimState& s) {
    if (--until > 0) return;
    until = every;
    const double e = TotalEnergy(model, s);
    if (std::isfinite(e)) max_energy = std::fmax(max_energy, e);
  }
};

StabilityCell RunCell(const CreatureModel& creature, const MotorProgram& program,
                      IntegratorKind kind, double multiplier, double dt, double duration) {
  CreatureModel model = creature;
  for (double& k : model.stiffness) k *= multiplier;
  const Genome genome(MakeGenomeLayout(model, program, false));
  MotorController controller(model, program, PerturbedRestLengths(model, program, genome), dt);
  SimState state = MakeRestState(model);
  const double e0 = TotalEnergy(model, state);
  RunOptions run;
  run.dt = dt;
  run.duration = duration;
  run.integrator = kind;
  EnergyObserver energy{model};
  const RunResult result = Simulate(model, controller, state, run, energy);
  StabilityCell cell;
  cell.integrator = kind;
  cell.stiffness_multiplier = multiplier;
  cell.dt = dt;
  cell.stable = !result.diverged;
  cell.diverge_time = result.diverge_time;
  cell.max_energy_ratio = std::fmax(energy.max_energy, e0) / e0;
  return cell;
}

void RunDrift(const CreatureModel& creature, IntegratorKind kind, const StabilityOptions& options,
              std::vector<DriftSample>& out) {
  FreeFlight flight = MakeFreeFlight(creature, false);
  SimState s = flight.initial;
  const double e0 = TotalEnergy(flight.model, s);
  const long long total = std::llround(options.drift_duration / options.drift_dt);
  const long long every =
      std::max(1LL, std::llround(options.drift_sample_interval / options.drift_dt));
  out.push_back({kind, 0.0, 0.0});
  WithStepper(kind, flight.model, [&](auto& stepper) {
    stepper.Begin(flight.model, s);
    for (long long k = 1; k <= total; ++k) {
      stepper.Step(flight.model, s, options.drift_dt);
      if (k % every != 0) continue;
      const double drift = (TotalEnergy(flight.model, s) - e0) / flight.vibration_energy;
      // Past 10^12 of the vibration energy the run has blown up: stop before inf and NaN.
      if (!std::isfinite(drift) || std::fabs(drift) > 1e12) break;
      out.push_back({kind, static_cast<double>(k) * options.drift_dt, drift});
    }
  });
}

GenomeStressRow Classify(const std::string& name, const std::vector<Individual>& people,
                         size_t begin, size_t end) {
  GenomeStressRow row;
  row.name = name;
  row.min_distance = INFINITY;
  row.max_distance = -INFINITY;
  for (size_t i = begin; i < end; ++i) {
    const RunResult& r = people[i].result;
    ++row.runs;
    if (!std::isfinite(r.distance)) ++row.non_finite;
    if (r.diverged) {
      ++row.diverged;
    } else if (r.fell) {
      ++row.fell;
    } else {
      ++row.walked;
    }
    if (!r.diverged) {
      row.min_distance = std::fmin(row.min_distance, r.distance);
      row.max_distance = std::fmax(row.max_distance, r.distance);
    }
  }
  return row;
}

}  // namespace

StabilityReport RunStabilityBench(const CreatureModel& model, const MotorProgram& program,
                                  const StabilityOptions& options, const LogLine& note) {
  StabilityReport report;
  for (IntegratorKind kind : options.integrators) {
    for (double multiplier : options.stiffness_multipliers) {
      int stable = 0, run = 0;
      for (double dt : options.steps) {
        if (kind == IntegratorKind::kImplicitEuler && dt < options.implicit_min_dt * (1 - 1e-9))
          continue;
        report.cells.push_back(RunCell(model, program, kind, multiplier, dt, options.map_duration));
        stable += report.cells.back().stable;
        ++run;
      }
      note("map " + IntegratorName(kind) + " stiffness x" + Format("%g", multiplier) + ": " +
           std::to_string(stable) + " of " + std::to_string(run) + " steps stable");
    }
  }
  for (IntegratorKind kind : options.integrators) {
    note("energy drift " + IntegratorName(kind));
    RunDrift(model, kind, options, report.drift);
  }

  // Extreme and random genomes, the paper's integrator and step, evaluated in parallel.
  const auto layout = MakeGenomeLayout(model, program, false);
  std::vector<Individual> people;
  for (int value : {-8, 7}) {
    Genome g(layout);
    for (int i = 0; i < g.num_genes(); ++i) g.set_gene(i, value);
    people.push_back({g, {}, 0});
  }
  for (int n = 0; n < options.random_genomes; ++n) {
    Rng rng = Rng::ForStream(options.seed, static_cast<uint64_t>(n));
    Genome g(layout);
    for (int i = 0; i < g.num_genes(); ++i) g.set_gene(i, static_cast<int>(rng.NextBelow(16)) - 8);
    people.push_back({g, {}, 0});
  }
  std::vector<int> pending(people.size());
  for (size_t i = 0; i < people.size(); ++i) pending[i] = static_cast<int>(i);
  note("genomes: all -8, all +7 and " + std::to_string(options.random_genomes) +
       " random (euler, dt 0.0025)");
  EvaluatorConfig config;
  config.threads = options.threads;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  EvaluatePending(*evaluator, model, program, people, pending,
                  [&](std::string_view, long long done, long long total) {
                    if ((done > 0 && done % 100 == 0) || done == total)
                      note("genomes " + std::to_string(done) + "/" + std::to_string(total));
                  });
  report.genomes.push_back(Classify("all -8", people, 0, 1));
  report.genomes.push_back(Classify("all +7", people, 1, 2));
  report.genomes.push_back(Classify("random", people, 2, people.size()));
  return report;
}

std::string StabilityCsv(const StabilityReport& report) {
  std::ostringstream out;
  out << "integrator,stiffness_multiplier,dt,stable,max_energy_ratio\n";
  for (const StabilityCell& c : report.cells) {
    out << IntegratorName(c.integrator) << ',' << Format("%g", c.stiffness_multiplier) << ','
        << Format("%.9g", c.dt) << ',' << (c.stable ? 1 : 0) << ','
        << Format("%.6g", c.max_energy_ratio) << '\n';
  }
  return out.str();
}

std::string EnergyDriftCsv(const StabilityReport& report) {
  std::ostringstream out;
  out << "integrator,time,energy_relative_drift\n";
  for (const DriftSample& d : report.drift) {
    out << IntegratorName(d.integrator) << ',' << Format("%g", d.time) << ','
        << Format("%.6e", d.drift) << '\n';
  }
  return out.str();
}

std::string StabilitySummary(const StabilityReport& report) {
  std::ostringstream out;
  char line[256];
  // (a) For each integrator and multiplier, the largest stable step (with no diverged step
  // below it among those run).
  out << "Largest stable step (every spring's stiffness multiplied; 20 time units of the "
         "unoptimised program; '-' none):\n";
  std::vector<IntegratorKind> kinds;
  std::vector<double> multipliers;
  for (const StabilityCell& c : report.cells) {
    if (std::find(kinds.begin(), kinds.end(), c.integrator) == kinds.end())
      kinds.push_back(c.integrator);
    if (std::find(multipliers.begin(), multipliers.end(), c.stiffness_multiplier) ==
        multipliers.end())
      multipliers.push_back(c.stiffness_multiplier);
  }
  std::snprintf(line, sizeof line, "%-17s", "integrator");
  out << line;
  for (double m : multipliers) out << Format("  x%-9g", m);
  out << '\n';
  for (IntegratorKind kind : kinds) {
    std::snprintf(line, sizeof line, "%-17s", IntegratorName(kind).c_str());
    out << line;
    for (double m : multipliers) {
      double largest = 0;
      for (const StabilityCell& c : report.cells) {
        if (c.integrator == kind && c.stiffness_multiplier == m && c.stable)
          largest = std::fmax(largest, c.dt);
      }
      out << (largest > 0 ? Format("  %-10.6g", largest) : std::string("  -         "));
    }
    out << '\n';
  }

  // (b) Energy drift: final and extreme values per integrator.
  out << "\nEnergy drift in free flight (gravity on, ground and damping off), relative to the "
         "initial vibration energy:\n";
  for (IntegratorKind kind : kinds) {
    double last_time = 0, last = 0, max_abs = 0;
    for (const DriftSample& d : report.drift) {
      if (d.integrator != kind) continue;
      last_time = d.time;
      last = d.drift;
      max_abs = std::fmax(max_abs, std::fabs(d.drift));
    }
    std::snprintf(line, sizeof line, "  %-17s at t = %-6g %+.3e   max |drift| %.3e\n",
                  IntegratorName(kind).c_str(), last_time, last, max_abs);
    out << line;
  }

  // (c) Genomes.
  out << "\nExtreme and random genomes (euler, dt 0.0025, 1000 time units):\n";
  std::snprintf(line, sizeof line, "  %-8s %6s %7s %6s %9s %11s  %s\n", "genomes", "runs", "walked",
                "fell", "diverged", "silent NaN", "distance range (not diverged)");
  out << line;
  for (const GenomeStressRow& g : report.genomes) {
    std::snprintf(line, sizeof line, "  %-8s %6d %7d %6d %9d %11d  [%.3f, %.3f]\n", g.name.c_str(),
                  g.runs, g.walked, g.fell, g.diverged, g.non_finite, g.min_distance,
                  g.max_distance);
    out << line;
  }
  return out.str();
}

}  // namespace hexgait
