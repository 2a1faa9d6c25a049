#include "bench/accuracy.h"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <utility>

#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/rest_schedule.h"
#include "sim/batch_evaluate.h"
#include "sim/reference.h"
#include "sim/step_loop.h"
#include "util/clock.h"

namespace hexgait {
namespace {

using Positions = std::vector<Eigen::Vector3d>;

Positions PositionsOf(const SimState& s) {
  Positions p(s.num_particles());
  for (int i = 0; i < s.num_particles(); ++i) p[i] = s.position(i);
  return p;
}

// Max over particles of the distance between two configurations (the error norm of the table).
double MaxDistance(const Positions& a, const Positions& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::fmax(worst, (a[i] - b[i]).norm());
  return worst;
}

// Copies the positions when the run reaches two given step numbers. A comparison per step is
// noise next to the force evaluation, so the timing stays honest.
struct SnapshotObserver {
  long long step_a = 0, step_b = 0;
  Positions a, b;
  void OnStep(const SimState& s) {
    if (s.step == step_a) a = PositionsOf(s);
    if (s.step == step_b) b = PositionsOf(s);
  }
};

struct ReferenceRun {
  Positions at_short, at_cycle;
  double fitness = 0;
  long long steps = 0;
  double wall_s = 0;
};

ReferenceRun RunReference(const CreatureModel& model, const MotorProgram& program,
                          const Genome& genome, const AccuracyOptions& options, double cycle_time,
                          double tolerance) {
  const auto start = Clock::now();
  const SimState initial = MakeRestState(model);
  const RestLengthSchedule schedule(model, program, PerturbedRestLengths(model, program, genome),
                                    initial.rest_length, options.duration);
  ReferenceSolver ref(model, &schedule, initial, tolerance);
  ReferenceRun run;
  ref.AdvanceTo(options.short_horizon);
  run.at_short = PositionsOf(ref.state());
  ref.AdvanceTo(cycle_time);
  run.at_cycle = PositionsOf(ref.state());
  ref.AdvanceTo(options.duration);
  run.fitness = BodyCentre(model, ref.state()).x() - BodyCentre(model, initial).x();
  run.steps = ref.steps();
  run.wall_s = SecondsSince(start);
  return run;
}

// CPU seconds of the calling thread: the cost of a single-threaded run, unaffected by other
// processes sharing the machine (on an idle core it equals the wall time).
double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// What one run of the ladder gives: positions at the two snapshot steps, the distance at the
// end, whether it stayed stable, and the time it reached.
struct LadderRun {
  Positions a, b;
  double fitness = 0;
  bool stable = false;
  double end_time = 0;
};

// The row for a run against the reference, `seconds` being its CPU time.
AccuracyRow ScoreRun(IntegratorKind kind, Precision precision, const std::string& program,
                     double dt, const LadderRun& run, const ReferenceRun& ref, double seconds) {
  AccuracyRow row;
  row.integrator = kind;
  row.precision = precision;
  row.program = program;
  row.dt = dt;
  row.stable = run.stable;
  row.wall_s_per_1000tu = run.end_time > 0 ? seconds * 1000.0 / run.end_time : 0;
  if (row.stable) {
    row.pos_error_t10 = MaxDistance(run.a, ref.at_short);
    row.pos_error_cycle1 = MaxDistance(run.b, ref.at_cycle);
    row.fitness = run.fitness;
    row.fitness_rel_error = std::fabs(run.fitness - ref.fitness) / std::fabs(ref.fitness);
  }
  return row;
}

bool AllFinite(const Positions& p) {
  for (const Eigen::Vector3d& v : p) {
    if (!v.allFinite()) return false;
  }
  return true;
}

// Explicit Euler in one float lane of the batched kernel; unstable if any position it reports
// is not finite.
LadderRun RunFloatLane(const CreatureModel& model, const MotorProgram& program,
                       const Genome& genome, double dt, long long step_a, long long step_b,
                       long long total) {
  BatchSimulation<float> sim(model, program, PerturbedRestLengths(model, program, {&genome}), dt,
                             1);
  SimState s = MakeRestState(model);
  sim.Extract(0, s);
  const double start_x = BodyCentre(model, s).x();
  LadderRun run;
  sim.Advance(step_a);
  sim.Extract(0, s);
  run.a = PositionsOf(s);
  sim.Advance(step_b - step_a);
  sim.Extract(0, s);
  run.b = PositionsOf(s);
  sim.Advance(total - step_b);
  sim.Extract(0, s);
  run.fitness = BodyCentre(model, s).x() - start_x;
  run.end_time = sim.time();
  run.stable = AllFinite(run.a) && AllFinite(run.b) && AllFinite(PositionsOf(s));
  return run;
}

}  // namespace

std::string MethodName(const AccuracyRow& row) {
  return IntegratorName(row.integrator) + (row.precision == Precision::kFloat ? "-float" : "");
}

std::vector<double> DefaultStepLadder() {
  std::vector<double> ladder;
  for (int j = 0; j <= 6; ++j) ladder.push_back(0.01 / static_cast<double>(1 << j));
  return ladder;
}

AccuracyReport RunAccuracyBench(const CreatureModel& model, const MotorProgram& program,
                                const std::vector<AccuracyProgram>& programs,
                                const AccuracyOptions& options, const LogLine& note) {
  AccuracyReport report;
  report.cycle_time = program.cycle_period;
  const auto add_row = [&](const AccuracyRow& row, double seconds) {
    report.rows.push_back(row);
    note(MethodName(row) + " " + row.program + " dt " + Format("%g", row.dt) + ": " +
         (row.stable ? "error at cycle end " + Format("%.3g", row.pos_error_cycle1)
                     : std::string("diverged")) +
         ", " + Format("%.2f", seconds) + " s");
  };
  for (const AccuracyProgram& prog : programs) {
    note("reference for " + prog.name + " (dopri5, tolerance " +
         Format("%g", options.reference_tolerance) + " and half of it)");
    const ReferenceRun ref = RunReference(model, program, prog.genome, options, report.cycle_time,
                                          options.reference_tolerance);
    const ReferenceRun half = RunReference(model, program, prog.genome, options, report.cycle_time,
                                           0.5 * options.reference_tolerance);
    ReferenceReport rr;
    rr.program = prog.name;
    rr.fitness = ref.fitness;
    rr.steps = ref.steps;
    rr.wall_s = ref.wall_s;
    rr.halving_change_t10 = MaxDistance(ref.at_short, half.at_short);
    rr.halving_change_cycle1 = MaxDistance(ref.at_cycle, half.at_cycle);
    rr.halving_change_fitness_rel = std::fabs(ref.fitness - half.fitness) / std::fabs(ref.fitness);
    report.references.push_back(rr);

    for (IntegratorKind kind : options.integrators) {
      for (double dt : options.steps) {
        if (kind == IntegratorKind::kImplicitEuler && dt < options.implicit_min_dt * (1 - 1e-9))
          continue;
        MotorController controller(model, program,
                                   PerturbedRestLengths(model, program, prog.genome), dt);
        SimState state = MakeRestState(model);
        RunOptions run;
        run.dt = dt;
        run.duration = options.duration;
        run.integrator = kind;
        SnapshotObserver snapshots;
        snapshots.step_a = std::llround(options.short_horizon / dt);
        snapshots.step_b = std::llround(report.cycle_time / dt);
        const double start = ThreadSeconds();
        const RunResult result = Simulate(model, controller, state, run, snapshots);
        const double wall = ThreadSeconds() - start;
        LadderRun ladder;
        ladder.stable = !result.diverged && !snapshots.a.empty() && !snapshots.b.empty();
        ladder.a = std::move(snapshots.a);
        ladder.b = std::move(snapshots.b);
        ladder.fitness = result.distance;
        ladder.end_time = result.end_time;
        add_row(ScoreRun(kind, Precision::kDouble, prog.name, dt, ladder, ref, wall), wall);
      }
    }
    const bool has_euler = std::find(options.integrators.begin(), options.integrators.end(),
                                     IntegratorKind::kEuler) != options.integrators.end();
    if (!options.float_lanes || !has_euler) continue;
    for (double dt : options.steps) {
      const long long step_a = std::llround(options.short_horizon / dt);
      const long long step_b = std::llround(report.cycle_time / dt);
      const long long total = std::llround(options.duration / dt);
      const double start = ThreadSeconds();
      const LadderRun run = RunFloatLane(model, program, prog.genome, dt, step_a, step_b, total);
      const double wall = ThreadSeconds() - start;
      add_row(ScoreRun(IntegratorKind::kEuler, Precision::kFloat, prog.name, dt, run, ref, wall),
              wall);
    }
  }
  return report;
}

std::string AccuracyCsv(const AccuracyReport& report) {
  std::ostringstream out;
  out << "integrator,program,dt,stable,pos_error_t10,pos_error_cycle1,fitness,fitness_rel_error,"
         "wall_s_per_1000tu\n";
  for (const AccuracyRow& r : report.rows) {
    out << MethodName(r) << ',' << r.program << ',' << Format("%.9g", r.dt) << ','
        << (r.stable ? 1 : 0) << ',';
    if (r.stable) {
      out << Format("%.6e", r.pos_error_t10) << ',' << Format("%.6e", r.pos_error_cycle1) << ','
          << Format("%.9g", r.fitness) << ',' << Format("%.6e", r.fitness_rel_error);
    } else {
      out << ",,,";
    }
    out << ',' << Format("%.6g", r.wall_s_per_1000tu) << '\n';
  }
  return out.str();
}

std::string AccuracySummary(const AccuracyReport& report) {
  std::ostringstream out;
  char line[256];
  out << "Reference: Boost.Odeint runge_kutta_dopri5, adaptive, restarted at every rest-length "
         "kink.\n";
  for (const ReferenceReport& r : report.references) {
    std::snprintf(line, sizeof line,
                  "  %-11s fitness %.6f, %lld steps, %.1f s; halving the tolerance changes "
                  "positions by %.1e (t=10), %.1e (cycle end), fitness by %.1e (relative)\n",
                  r.program.c_str(), r.fitness, r.steps, r.wall_s, r.halving_change_t10,
                  r.halving_change_cycle1, r.halving_change_fitness_rel);
    out << line;
  }
  out << "\nPosition error: max over particles of |x - x_ref|, at t = 10 and at the end of the "
         "first gait cycle (t = "
      << Format("%g", report.cycle_time) << ").\n\n";
  std::snprintf(line, sizeof line, "%-17s %-11s %-10s %-6s %-10s %-10s %-11s %-10s %s\n",
                "integrator", "program", "dt", "stable", "err_t10", "err_cycle1", "fitness",
                "fit_relerr", "wall_s/1000TU");
  out << line;
  for (const AccuracyRow& r : report.rows) {
    if (r.stable) {
      std::snprintf(line, sizeof line,
                    "%-17s %-11s %-10.8g %-6s %-10.2e %-10.2e %-11.5f %-10.2e %.3f\n",
                    MethodName(r).c_str(), r.program.c_str(), r.dt, "yes", r.pos_error_t10,
                    r.pos_error_cycle1, r.fitness, r.fitness_rel_error, r.wall_s_per_1000tu);
    } else {
      std::snprintf(line, sizeof line, "%-17s %-11s %-10.8g %-6s %-10s %-10s %-11s %-10s %.3f\n",
                    MethodName(r).c_str(), r.program.c_str(), r.dt, "no", "-", "-", "-", "-",
                    r.wall_s_per_1000tu);
    }
    out << line;
  }

  // Largest stable step of the ladder, per program and integrator.
  out << "\nLargest stable step of the ladder:\n";
  for (const ReferenceReport& ref : report.references) {
    out << "  " << ref.program << ':';
    std::vector<std::string> methods;
    for (const AccuracyRow& r : report.rows) {
      if (r.program == ref.program &&
          std::find(methods.begin(), methods.end(), MethodName(r)) == methods.end())
        methods.push_back(MethodName(r));
    }
    for (const std::string& method : methods) {
      double largest = 0;
      for (const AccuracyRow& r : report.rows) {
        if (r.program == ref.program && MethodName(r) == method && r.stable)
          largest = std::fmax(largest, r.dt);
      }
      out << ' ' << method << ' ' << (largest > 0 ? Format("%g", largest) : std::string("none"));
    }
    out << '\n';
  }

  // The paper's accuracy: explicit Euler's error at the end of the first cycle at dt 0.0025.
  out << "\nFastest way to the paper's accuracy (error at the cycle end <= explicit Euler's at "
         "dt 0.0025):\n";
  for (const ReferenceReport& ref : report.references) {
    const AccuracyRow* paper = nullptr;
    for (const AccuracyRow& r : report.rows) {
      if (r.program == ref.program && r.integrator == IntegratorKind::kEuler &&
          r.precision == Precision::kDouble && r.stable && std::fabs(r.dt - 0.0025) < 1e-12)
        paper = &r;
    }
    if (!paper) continue;
    const AccuracyRow* best = nullptr;
    for (const AccuracyRow& r : report.rows) {
      if (r.program != ref.program || !r.stable || r.pos_error_cycle1 > paper->pos_error_cycle1)
        continue;
      if (!best || r.wall_s_per_1000tu < best->wall_s_per_1000tu) best = &r;
    }
    std::snprintf(line, sizeof line,
                  "  %-11s paper: euler dt 0.0025 error %.2e in %.3f s/1000TU; fastest: %s dt %g "
                  "error %.2e in %.3f s/1000TU (%.1fx faster)\n",
                  ref.program.c_str(), paper->pos_error_cycle1, paper->wall_s_per_1000tu,
                  MethodName(*best).c_str(), best->dt, best->pos_error_cycle1,
                  best->wall_s_per_1000tu, paper->wall_s_per_1000tu / best->wall_s_per_1000tu);
    out << line;
  }
  return out.str();
}

}  // namespace hexgait
