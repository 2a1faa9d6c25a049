#include "study/endurance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "eval/evaluator.h"
#include "ga/genome_eval.h"
#include "ga/rng.h"
#include "motor/controller.h"
#include "sim/step_loop.h"
#include "sim/trace.h"
#include "util/error.h"
#include "util/parallel_for.h"

namespace hexgait {
namespace {

// Rng streams: one for the push phases, one per jittered creature, one per batch of random
// genomes; far apart so they never meet.
constexpr uint64_t kPushStream = 1;
constexpr uint64_t kJitterStream = 1000;
constexpr uint64_t kRandomGenomeStream = 1000000;

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// Gravity tilted by `degrees` about the y axis, as the ground would be: positive climbs while
// walking along +x.
CreatureModel OnSlope(const CreatureModel& model, double degrees) {
  CreatureModel sloped = model;
  const double angle = degrees * std::numbers::pi / 180.0;
  sloped.physics.gravity = model.physics.gravity * std::cos(angle);
  sloped.physics.gravity_x = -model.physics.gravity * std::sin(angle);
  return sloped;
}

// Every spring's stiffness and every particle's mass times its own factor in [1 - j, 1 + j].
CreatureModel Jittered(const CreatureModel& model, double jitter, uint64_t seed, int trial) {
  CreatureModel built = model;
  Rng rng = Rng::ForStream(seed, kJitterStream + static_cast<uint64_t>(trial));
  const auto factor = [&] { return 1.0 + jitter * (2.0 * rng.NextDouble() - 1.0); };
  for (double& k : built.stiffness) k *= factor();
  for (int i = 0; i < built.num_particles(); ++i) {
    built.mass[i] *= factor();
    built.inv_mass[i] = 1.0 / built.mass[i];
  }
  return built;
}

// The push's time in trial `trial`: just after the test, at a random phase of the gait cycle,
// on a step. The same phases for every gait: they share the motor program's clock.
double PushTime(const EnduranceSettings& s, double cycle_period, int trial) {
  Rng rng = Rng::ForStream(s.seed, kPushStream);
  double phase = 0;
  for (int t = 0; t <= trial; ++t) phase = rng.NextDouble();
  const double time = s.test.duration + phase * cycle_period;
  return std::round(time / s.test.dt) * s.test.dt;
}

// One gait's unperturbed run to `horizon` (or its fall), its body centre sampled every
// `interval` time units.
EndurancePath TracePath(const CreatureModel& model, const MotorProgram& program,
                        const RestLengthTable& table, RunOptions run, double interval) {
  // The length is measured a gait cycle at a time: the body's sway within a cycle is not
  // walking.
  const size_t stride =
      std::max<size_t>(1, static_cast<size_t>(std::llround(program.cycle_period / interval)));
  run.stop_at_fall = true;
  MotorController controller(model, program, table, run.dt);
  SimState state = MakeRestState(model);
  TraceRecorder trace(model, std::max(1LL, std::llround(interval / run.dt)));
  trace.Record(state);
  Simulate(model, controller, state, run, trace);
  EndurancePath path;
  for (const TraceSample& sample : trace.samples()) {
    path.time.push_back(sample.time);
    path.x.push_back(sample.centre.x());
    path.y.push_back(sample.centre.y());
  }
  for (size_t i = stride; i < path.x.size(); i += stride) {
    path.length += std::hypot(path.x[i] - path.x[i - stride], path.y[i] - path.y[i - stride]);
  }
  return path;
}

// Every gait's path, on `threads` threads; each gait's run is independent, so the result does
// not depend on the count.
std::vector<EndurancePath> TracePaths(const CreatureModel& model, const MotorProgram& program,
                                      const std::vector<RestLengthTable>& tables,
                                      const RunOptions& run, double interval, int threads) {
  std::vector<EndurancePath> paths(tables.size());
  ParallelFor(tables.size(), ResolveThreadCount(threads),
              [&](size_t g) { paths[g] = TracePath(model, program, tables[g], run, interval); });
  return paths;
}

}  // namespace

void CheckEnduranceSettings(const EnduranceSettings& s) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError(what);
  };
  require(s.long_factor >= 1 && s.long_factor <= 1e4, "--long must be 1 to 10000 (times the test)");
  require(s.perturbed_factor >= 2 && s.perturbed_factor <= s.long_factor,
          "--horizon must be from 2 to --long (times the test)");
  require(std::isfinite(s.push_impulse) && s.push_impulse >= 0,
          "--push must be 0 (no push) or more");
  require(s.slope_degrees >= 0 && s.slope_degrees < 45,
          "--slope must be from 0 (none) to under 45 degrees");
  require(s.jitter >= 0 && s.jitter <= 0.5, "--jitter must be from 0 to 0.5");
  require(s.trials >= 1 && s.trials <= 1000, "--trials must be 1 to 1000");
  require(s.path_interval > 0 && s.path_interval <= s.test.duration,
          "--path-interval must be over 0 and at most the test's time");
  require(s.step_factor > 0 && s.step_factor <= 1, "--step-factor must be over 0 and at most 1");
}

std::vector<EnduranceCondition> EnduranceConditions(const EnduranceSettings& s,
                                                    IntegratorKind test_integrator) {
  const double test = s.test.duration;
  const double perturbed = s.perturbed_factor * test;
  std::vector<EnduranceCondition> list;
  list.push_back({Perturbation::kNone, "none", "no perturbation", s.long_factor * test, 1});
  if (s.push_impulse > 0) {
    list.push_back({Perturbation::kPush, "push",
                    "push sideways, impulse " + Number(s.push_impulse) + ", random phase",
                    perturbed, s.trials});
  }
  if (s.slope_degrees > 0) {
    list.push_back({Perturbation::kSlopeUp, "slope-up",
                    "uphill, " + Number(s.slope_degrees) + " degrees", perturbed, 1});
    list.push_back({Perturbation::kSlopeDown, "slope-down",
                    "downhill, " + Number(s.slope_degrees) + " degrees", perturbed, 1});
  }
  if (s.jitter > 0) {
    list.push_back({Perturbation::kJitter, "jitter",
                    "stiffness and mass +-" + Number(100 * s.jitter) + "%", perturbed, s.trials});
  }
  if (s.other_integrator != test_integrator) {
    const std::string name = IntegratorName(s.other_integrator);
    list.push_back({Perturbation::kIntegrator, name, name + " integrator", perturbed, 1});
  }
  if (s.step_factor != 1) {
    list.push_back(
        {Perturbation::kStep, "step",
         "step " + Number(s.step_factor * s.test.dt) + " (test: " + Number(s.test.dt) + ")",
         perturbed, 1, s.step_factor});
  }
  return list;
}

EnduranceResult RunEndurance(const CreatureModel& model, const MotorProgram& program,
                             std::span<const EnduranceGait> gaits, const EnduranceSettings& s,
                             const Progress& on_progress) {
  CheckEnduranceSettings(s);
  if (gaits.empty()) throw InputError("no gaits to run");
  EnduranceResult out;
  out.conditions = EnduranceConditions(s, s.test.integrator);
  std::vector<RestLengthTable> tables;
  for (const EnduranceGait& g : gaits) tables.push_back(g.table);
  const int n = static_cast<int>(gaits.size());
  const double cycle_period = program.cycle_period;

  // Work in gait-time units at the test's step: the test, the traced paths (scalar: about four
  // times the batched runs' cost), every condition (a finer step's time units cost more).
  const double path_work = 4 * s.perturbed_factor * s.test.duration * n;
  double total_work = s.test.duration * n + path_work, work_done = 0;
  for (const EnduranceCondition& c : out.conditions) {
    total_work += c.horizon / c.step_fraction * c.trials * n;
  }
  const auto report = [&](double work) {
    if (on_progress) {
      on_progress("time units simulated (at the test's step)", std::llround(work),
                  std::llround(total_work));
    }
  };
  {
    EvaluatorConfig config;
    config.threads = s.threads;
    config.run = s.test;
    out.test =
        MakeLocalEvaluator(model, program, config)
            ->Evaluate(tables, [&](std::string_view, long long done, long long all) {
              report(s.test.duration * n * static_cast<double>(done) / static_cast<double>(all));
            });
    work_done = s.test.duration * n;
  }
  RunOptions path_run = s.test;
  path_run.duration = s.perturbed_factor * s.test.duration;
  out.paths = TracePaths(model, program, tables, path_run, s.path_interval, s.threads);
  work_done += path_work;
  report(work_done);
  for (int ci = 0; ci < static_cast<int>(out.conditions.size()); ++ci) {
    const EnduranceCondition& c = out.conditions[ci];
    for (int trial = 0; trial < c.trials; ++trial) {
      EvaluatorConfig config;
      config.threads = s.threads;
      config.run = s.test;
      config.run.duration = c.horizon;
      config.run.stop_at_fall = true;
      config.run.early_stop = false;
      const CreatureModel* run_model = &model;
      CreatureModel changed;
      double push_time = 0;
      switch (c.perturbation) {
        case Perturbation::kNone:
          break;
        case Perturbation::kPush:
          push_time = PushTime(s, cycle_period, trial);
          config.run.push_time = push_time;
          config.run.push_impulse = s.push_impulse;
          break;
        case Perturbation::kSlopeUp:
        case Perturbation::kSlopeDown:
          changed = OnSlope(
              model, c.perturbation == Perturbation::kSlopeUp ? s.slope_degrees : -s.slope_degrees);
          run_model = &changed;
          break;
        case Perturbation::kJitter:
          changed = Jittered(model, s.jitter, s.seed, trial);
          run_model = &changed;
          break;
        case Perturbation::kIntegrator:
          config.run.integrator = s.other_integrator;
          break;
        case Perturbation::kStep:
          config.run.dt = s.test.dt * c.step_fraction;
          // The checks stay 0.1 time units apart, as at the test's step.
          config.run.check_interval = CheckIntervalFor(config.run.dt);
          break;
      }
      const auto evaluator = MakeLocalEvaluator(*run_model, program, config);
      const double work = c.horizon / c.step_fraction * n;
      const std::vector<RunResult> results =
          evaluator->Evaluate(tables, [&](std::string_view, long long done, long long total) {
            report(work_done + work * static_cast<double>(done) / static_cast<double>(total));
          });
      work_done += work;
      for (int g = 0; g < n; ++g) out.runs.push_back({g, ci, trial, push_time, results[g]});
    }
  }
  report(total_work);
  return out;
}

double FallTime(const RunResult& r) {
  if (r.fell) return r.fall_time;
  if (r.diverged) return r.diverge_time;
  return INFINITY;
}

std::vector<std::pair<double, double>> SurvivalCurve(std::vector<double> fall_times,
                                                     double horizon) {
  std::sort(fall_times.begin(), fall_times.end());
  const double n = static_cast<double>(fall_times.size());
  std::vector<std::pair<double, double>> curve{{0.0, 1.0}};
  size_t fallen = 0;
  while (fallen < fall_times.size() && fall_times[fallen] <= horizon) {
    const double t = fall_times[fallen];
    while (fallen < fall_times.size() && fall_times[fallen] == t) ++fallen;
    curve.emplace_back(t, n > 0 ? 1.0 - static_cast<double>(fallen) / n : 0.0);
  }
  curve.emplace_back(horizon, n > 0 ? 1.0 - static_cast<double>(fallen) / n : 0.0);
  return curve;
}

std::vector<Genome> StandingRandomGenomes(const CreatureModel& model, const MotorProgram& program,
                                          std::shared_ptr<const GenomeLayout> layout, int count,
                                          int max_tries, const RunOptions& test, uint64_t seed,
                                          int threads, int* tried) {
  constexpr int kBatch = 64;  // drawn and run together; fixed, so `tried` is too
  EvaluatorConfig config;
  config.run = test;
  config.threads = threads;
  const auto evaluator = MakeLocalEvaluator(model, program, config);
  std::vector<Genome> found;
  int drawn = 0;
  for (uint64_t batch = 0; static_cast<int>(found.size()) < count && drawn < max_tries; ++batch) {
    Rng rng = Rng::ForStream(seed, kRandomGenomeStream + batch);
    std::vector<Genome> candidates;
    for (int i = 0; i < kBatch && drawn < max_tries; ++i, ++drawn) {
      Genome g(layout);
      for (int gene = 0; gene < g.num_genes(); ++gene) {
        g.set_gene(gene, kGeneMin + static_cast<int>(rng.NextBelow(kGeneMax - kGeneMin + 1)));
      }
      candidates.push_back(std::move(g));
    }
    std::vector<const Genome*> pointers;
    for (const Genome& g : candidates) pointers.push_back(&g);
    const std::vector<RunResult> results =
        evaluator->Evaluate(PerturbedRestLengths(model, program, pointers));
    for (size_t i = 0; i < candidates.size() && static_cast<int>(found.size()) < count; ++i) {
      if (!results[i].fell && !results[i].diverged) found.push_back(std::move(candidates[i]));
    }
  }
  if (tried) *tried = drawn;
  return found;
}

}  // namespace hexgait
