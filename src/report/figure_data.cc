#include "report/figure_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "report/csv.h"
#include "report/number_text.h"
#include "util/error.h"

namespace hexgait {

std::vector<FitnessRow> ReadFitnessCsv(const std::string& path) {
  const CsvTable table = CsvTable::Read(path, {"generation", "best", "mean", "worst"});
  if (table.rows() == 0) throw InputError(path + ": no generations");
  std::vector<FitnessRow> rows;
  for (size_t r = 0; r < table.rows(); ++r) {
    FitnessRow row;
    const double generation = table.Number(r, "generation");
    if (generation != static_cast<double>(r)) {
      throw InputError(path + ": generation " + std::to_string(r) + " expected in row " +
                       std::to_string(r + 1));
    }
    row.generation = static_cast<int>(r);
    row.best = table.Number(r, "best");
    row.mean = table.Number(r, "mean");
    row.worst = table.Number(r, "worst");
    if (!std::isfinite(row.best) || !std::isfinite(row.mean) || !std::isfinite(row.worst)) {
      throw InputError(path + ": non-finite fitness in generation " + std::to_string(r));
    }
    rows.push_back(row);
  }
  return rows;
}

double ReadUnoptimizedDistance(const RunRecord& run, const std::string& source) {
  const double distance = run.unoptimized.distance;
  if (run.unoptimized.diverged) {
    throw InputError(source +
                     ": the unoptimized program's simulation diverged, so the fitness figure has "
                     "no distance to plot ratios to; run evolve again with a smaller --dt");
  }
  if (!(distance > 0) || !std::isfinite(distance)) {
    throw InputError(source + ": unoptimized.distance is " + Fixed(distance, 6) +
                     "; the fitness figure plots ratios to it, so it must be positive");
  }
  return distance;
}

ProgramTrace TraceProgram(const std::string& name, const CreatureModel& model,
                          const MotorProgram& program, const Genome& genome,
                          const RunOptions& options, double sample_interval,
                          const Progress& on_chunk) {
  ProgramTrace trace;
  trace.name = name;
  MotorController controller(model, program, PerturbedRestLengths(model, program, genome),
                             options.dt);
  SimState state = MakeRestState(model);
  const long long every = std::max(1LL, std::llround(sample_interval / options.dt));
  TraceRecorder recorder(model, every);
  recorder.Record(state);
  trace.result = SimulateInChunks(model, controller, state, options, recorder, 1 << 16,
                                  [&](long long done, long long total) {
                                    if (on_chunk) on_chunk("steps", done, total);
                                  });
  trace.samples = recorder.samples();
  return trace;
}

namespace {

// Intervals where bit `leg` of mask(sample) is set, for every leg.
template <class Mask>
std::vector<ContactInterval> BitIntervals(const std::vector<TraceSample>& samples, int num_legs,
                                          double until, Mask mask) {
  std::vector<ContactInterval> intervals;
  std::vector<unsigned> masks;
  for (const TraceSample& s : samples) masks.push_back(mask(s));
  for (int leg = 0; leg < num_legs; ++leg) {
    bool down = false;
    double start = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
      const TraceSample& s = samples[i];
      if (s.time >= until) break;
      const bool now = (masks[i] >> leg) & 1u;
      if (now && !down) start = s.time;
      if (!now && down) intervals.push_back({leg, start, s.time});
      down = now;
    }
    if (down) intervals.push_back({leg, start, until});
  }
  return intervals;
}

}  // namespace

std::vector<ContactInterval> FootContacts(const std::vector<TraceSample>& samples, int num_legs,
                                          double until) {
  return BitIntervals(samples, num_legs, until,
                      [](const TraceSample& s) { return s.feet_on_ground; });
}

std::vector<ContactInterval> CommandedSwings(const MotorProgram& program, int num_legs,
                                             const std::vector<TraceSample>& samples,
                                             double until) {
  int swing = -1;
  for (int p = 0; p < program.num_positions(); ++p) {
    if (program.positions[p].name == "swing") swing = p;
  }
  if (swing < 0) return {};
  return BitIntervals(samples, num_legs, until, [&](const TraceSample& s) {
    const std::vector<int> positions = LegPositionsAt(program, num_legs, s.time);
    unsigned mask = 0;
    for (int leg = 0; leg < num_legs; ++leg) mask |= (positions[leg] == swing ? 1u : 0u) << leg;
    return mask;
  });
}

std::string FitnessFigureCsv(const std::vector<FitnessRow>& rows, double unoptimized_distance) {
  std::ostringstream out;
  out << "generation,best,mean,worst,best_ratio,mean_ratio,worst_ratio\n";
  for (const FitnessRow& r : rows) {
    out << r.generation << ',' << Exact(r.best) << ',' << Exact(r.mean) << ',' << Exact(r.worst)
        << ',' << Exact(r.best / unoptimized_distance) << ','
        << Exact(r.mean / unoptimized_distance) << ',' << Exact(r.worst / unoptimized_distance)
        << '\n';
  }
  return out.str();
}

std::string FitnessSeedsCsv(const std::vector<SeedRun>& runs) {
  for (const SeedRun& run : runs) {
    if (run.rows.size() != runs[0].rows.size()) {
      throw InputError("--runs: " + run.dir + " has " + std::to_string(run.rows.size() - 1) +
                       " generations, " + runs[0].dir + " has " +
                       std::to_string(runs[0].rows.size() - 1));
    }
  }
  std::ostringstream out;
  out << "generation,runs,median_best_ratio,min_best_ratio,max_best_ratio,median_best,min_best,"
         "max_best\n";
  for (size_t g = 0; g < runs[0].rows.size(); ++g) {
    std::vector<double> best, ratio;
    for (const SeedRun& run : runs) {
      best.push_back(run.rows[g].best);
      ratio.push_back(run.rows[g].best / run.unoptimized_distance);
    }
    const auto [rlo, rhi] = std::minmax_element(ratio.begin(), ratio.end());
    const auto [blo, bhi] = std::minmax_element(best.begin(), best.end());
    out << g << ',' << runs.size() << ',' << Exact(Median(ratio)) << ',' << Exact(*rlo) << ','
        << Exact(*rhi) << ',' << Exact(Median(best)) << ',' << Exact(*blo) << ',' << Exact(*bhi)
        << '\n';
  }
  return out.str();
}

std::string GaitCsv(const CreatureModel& model, const MotorProgram& program,
                    const std::vector<ProgramTrace>& traces, double until) {
  const int legs = static_cast<int>(model.legs.size());
  std::ostringstream out;
  out << "program,kind,leg,leg_name,start,end\n";
  auto rows = [&](const std::string& name, const char* kind,
                  const std::vector<ContactInterval>& intervals) {
    for (const ContactInterval& c : intervals) {
      out << name << ',' << kind << ',' << c.leg << ',' << model.legs[c.leg].name << ','
          << Fixed(c.start, 4) << ',' << Fixed(c.end, 4) << '\n';
    }
  };
  rows("motor_program", "swing", CommandedSwings(program, legs, traces[0].samples, until));
  for (const ProgramTrace& trace : traces) {
    rows(trace.name, "contact", FootContacts(trace.samples, legs, until));
  }
  return out.str();
}

std::string BodyCsv(const std::vector<ProgramTrace>& traces, int stride) {
  std::ostringstream out;
  out << "time";
  for (const ProgramTrace& t : traces) {
    out << ',' << t.name << "_height," << t.name << "_pitch_degrees," << t.name << "_roll_degrees";
  }
  out << '\n';
  const size_t n = traces[0].samples.size();
  for (size_t i = 0; i < n; i += stride) {
    out << Fixed(traces[0].samples[i].time, 4);
    for (const ProgramTrace& t : traces) {
      const TraceSample& s = t.samples[i];
      out << ',' << Fixed(s.centre.z(), 6) << ',' << Fixed(s.pitch_degrees, 3) << ','
          << Fixed(s.roll_degrees, 3);
    }
    out << '\n';
  }
  return out.str();
}

std::string PathCsv(const std::vector<ProgramTrace>& traces, int stride) {
  std::ostringstream out;
  out << "time";
  for (const ProgramTrace& t : traces) out << ',' << t.name << "_x," << t.name << "_y";
  out << '\n';
  const size_t n = traces[0].samples.size();
  for (size_t i = 0; i < n; i += stride) {
    out << Fixed(traces[0].samples[i].time, 4);
    for (const ProgramTrace& t : traces) {
      out << ',' << Fixed(t.samples[i].centre.x(), 6) << ',' << Fixed(t.samples[i].centre.y(), 6);
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace hexgait
