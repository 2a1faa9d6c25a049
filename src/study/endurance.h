// How long an open-loop gait lasts, and how fragile it is (`hexgait endurance`). Each gait runs
// far past the test it was evolved for, then under perturbations a reader of the paper would
// try: a sideways push at a random phase of the gait cycle, a slope up and down, a creature
// built a few percent off, another integrator, a smaller step. Every run goes through the
// evaluator (eval/evaluator.h): batched where the kernels model the scene, on the scalar path
// where they do not (a push, a slope, another integrator), threaded either way, and the same
// bits for any thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"
#include "sim/integrator.h"
#include "sim/step_loop.h"
#include "util/progress.h"

namespace hexgait {

struct EnduranceGait {
  std::string group;  // which set it belongs to, e.g. "population 4, 10 generations"
  std::string name;   // where it came from, e.g. its genome file
  RestLengthTable table;
};

struct EnduranceSettings {
  RunOptions test;               // the evaluation the gaits were made for; duration: its time
  double long_factor = 100;      // the unperturbed run lasts long_factor x test.duration
  double perturbed_factor = 10;  // every perturbed run perturbed_factor x test.duration
  double push_impulse = 2.0;     // mass x length / time, along +y (sim/step_loop.h, RunOptions)
  double slope_degrees = 3;      // uphill and downhill
  double jitter = 0.05;          // every stiffness and mass times a factor in [1 - j, 1 + j]
  int trials = 4;                // push phases, and jittered creatures
  IntegratorKind other_integrator = IntegratorKind::kSymplecticEuler;
  double step_factor = 0.5;  // the other step: test.dt times this
  double path_interval = 5;  // time between the body-centre samples of the traced runs
  uint64_t seed = 1;         // push phases and jitter
  int threads = 0;           // 0: every CPU this process may use
};

enum class Perturbation { kNone, kPush, kSlopeUp, kSlopeDown, kJitter, kIntegrator, kStep };

struct EnduranceCondition {
  Perturbation perturbation = Perturbation::kNone;
  std::string name;   // for CSV files: none, push, slope-up, slope-down, jitter, ...
  std::string label;  // for figures and tables: "push sideways, impulse 2, random phase"
  double horizon = 0;
  int trials = 1;
  // The condition's step as a fraction of the test's (--step-factor for "step", else 1): a
  // time unit of it costs 1 / step_fraction of the test's steps.
  double step_fraction = 1;
};

struct EnduranceRun {
  int gait = 0, condition = 0, trial = 0;
  double push_time = 0;  // the push condition's; 0 otherwise
  RunResult result;
};

// A gait's body centre seen from above, unperturbed, to the perturbed horizon or its fall.
struct EndurancePath {
  std::vector<double> time, x, y;
  double length = 0;  // along the path, a gait cycle at a time: how far it walked, any way
};

struct EnduranceResult {
  std::vector<RunResult> test;                 // each gait's test run, as it was evolved for
  std::vector<EndurancePath> paths;            // each gait's, unperturbed
  std::vector<EnduranceCondition> conditions;  // "none" first
  std::vector<EnduranceRun> runs;              // by condition, trial, gait
};

// Throws InputError naming the flag of the first setting out of range (RunEndurance checks too;
// a command checks before it starts any work).
void CheckEnduranceSettings(const EnduranceSettings& settings);

// The conditions `settings` asks for, in the order RunEndurance runs them.
std::vector<EnduranceCondition> EnduranceConditions(const EnduranceSettings& settings,
                                                    IntegratorKind test_integrator);

// Every condition for every gait. `on_progress` counts the time units simulated, weighted by
// their cost at the test's step (the test, the traced paths at about four times a batched run's
// cost, every condition's runs, a finer step's at 1 / step_fraction). Throws InputError
// for bad settings or what the simulation throws.
EnduranceResult RunEndurance(const CreatureModel& model, const MotorProgram& program,
                             std::span<const EnduranceGait> gaits,
                             const EnduranceSettings& settings, const Progress& on_progress = {});

// When a run stopped standing: its fall, or its divergence (a blown-up integration is no gait),
// or +infinity when it stood to the end.
double FallTime(const RunResult& result);

// The fraction of runs still standing against time, from (0, 1) to (horizon, final fraction):
// a step curve with one point where each fall lands. `fall_times` from FallTime.
std::vector<std::pair<double, double>> SurvivalCurve(std::vector<double> fall_times,
                                                     double horizon);

// Random genomes (every gene uniform in [-8, 7]) that do not fall in `test`: up to `count`
// of them, from at most `max_tries` drawn; `tried` is set to how many were drawn. The same
// genomes for the same seed whatever the thread count.
std::vector<Genome> StandingRandomGenomes(const CreatureModel& model, const MotorProgram& program,
                                          std::shared_ptr<const GenomeLayout> layout, int count,
                                          int max_tries, const RunOptions& test, uint64_t seed,
                                          int threads, int* tried);

}  // namespace hexgait
