#include "report/figures.h"
#include "report/number_text.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "render/render_libraries.h"
#include "report/csv.h"
#include "report/figure1.h"
#include "report/figure_data.h"
#include "report/gnuplot.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/output.h"

namespace hexgait {
namespace {

constexpr double kPaperUnoptimized = 1064;
constexpr double kPaperEvolved = 4070;
// The fitness plots' y axis reaches this far above the highest value, so the key in the top
// left corner never covers a curve.
constexpr double kKeyRoom = 1.6;

// A round tic step (1, 2 or 5 times a power of ten) near `raw`.
double NiceStep(double raw) {
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / power;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * power;
}

// "falls at t = 192 (cycle 3)" / "does not fall".
std::string FallPhrase(const RunResult& r) {
  if (!r.fell) return "does not fall";
  return "falls at t = " + Fixed(r.fall_time, 0) + " (cycle " + std::to_string(r.fall_cycle) + ")";
}

nlohmann::json ResultJson(const RunResult& r) {
  nlohmann::json j;
  j["distance"] = r.distance;
  j["fell"] = r.fell;
  j["fall_time"] = r.fell ? nlohmann::json(r.fall_time) : nlohmann::json(nullptr);
  j["fall_cycle"] = r.fell ? nlohmann::json(r.fall_cycle) : nlohmann::json(nullptr);
  return j;
}

// Writes one figure's CSV and script into the staging folder, runs gnuplot, and records it.
class FigureWriter {
 public:
  FigureWriter(const AtomicDir& dir, nlohmann::json& manifest, const LogLine& log)
      : dir_(dir), manifest_(manifest), log_(log) {}

  void Plot(const std::string& name, const std::string& title, const std::string& caption,
            const std::string& csv, const std::string& body) {
    const auto start = Clock::now();
    WriteFileAtomically(dir_.File(name + ".csv"), csv);
    WriteFileAtomically(dir_.File(name + ".gp"), GnuplotScript(name, title, body));
    RunGnuplot(dir_.temp_path(), name + ".gp");
    Record(name, title, caption, {name + ".png", name + ".svg", name + ".csv", name + ".gp"});
    log_(name + ".png  " + title + "  (" + Fixed(SecondsSince(start), 2) + " s)");
  }
  void Record(const std::string& name, const std::string& title, const std::string& caption,
              const std::vector<std::string>& files) {
    manifest_["figures"].push_back(
        {{"name", name}, {"title", title}, {"caption", caption}, {"files", files}});
  }
  void Skip(const std::string& name, const std::string& reason) {
    manifest_["skipped"].push_back({{"name", name}, {"reason", reason}});
    log_("skipped " + name + ": " + reason);
  }

 private:
  const AtomicDir& dir_;
  nlohmann::json& manifest_;
  const LogLine& log_;
};

RunRecord ReadRunJson(const std::string& dir) {
  const std::string path = dir + "/run.json";
  return ParseRunRecord(ReadTextFile(path), path);
}

std::string RunLabel(const RunRecord& run) {
  return "seed " + std::to_string(run.seed) + ", population " + std::to_string(run.population) +
         ", " + std::to_string(run.generations) + " generations";
}

void FitnessFigure(FigureWriter& out, const FiguresOptions& options, const RunRecord& run) {
  const std::string run_json = options.run_dir + "/run.json";
  const std::vector<FitnessRow> rows = ReadFitnessCsv(options.run_dir + "/fitness.csv");
  const double unopt = ReadUnoptimizedDistance(run, run_json);
  const double paper = kPaperEvolved / kPaperUnoptimized;
  double top = std::max(1.0, paper), bottom = 0;
  for (const FitnessRow& r : rows) {
    top = std::max(top, r.best / unopt);
    bottom = std::min(bottom, r.worst / unopt);
  }
  const int last = rows.back().generation;
  std::ostringstream b;
  b << "  set title " << GnuplotText("Fitness per generation (" + RunLabel(run) + ")") << "\n"
    << "  set xlabel 'generation (0: initial population)'\n"
    << "  set ylabel 'fitness / unoptimized fitness (×)'\n"
    << "  set y2label 'distance walked (length units)'\n"
    << "  set xrange [-0.3:" << last + 0.3 << "]\n"
    << "  set xtics 1\n  set ytics nomirror\n"
    << "  set yrange [" << Fixed(bottom * 1.1, 3) << ":" << Fixed(top * kKeyRoom, 3) << "]\n"
    << "  set link y2 via y*" << unopt << " inverse y/" << unopt << "\n"
    << "  set y2tics " << NiceStep(top * kKeyRoom * unopt / 6) << "\n"
    << "  set key top left\n"
    << "  plot 'fitness.csv' using 1:5 with linespoints lw 3 pt 7 ps 1.4 lc "
    << Rgb(colours::kEvolved) << " title 'best', \\\n"
    << "       '' using 1:6 with linespoints lw 2.5 pt 5 ps 1.2 lc " << Rgb(colours::kMean)
    << " title 'mean', \\\n"
    << "       '' using 1:7 with linespoints lw 2.5 pt 9 ps 1.4 lc " << Rgb(colours::kWorst)
    << " title 'worst', \\\n"
    << "       " << paper << " with lines lw 3 dt 2 lc " << Rgb(colours::kPaper)
    << " title 'paper: 4070 / 1064 = 3.83×', \\\n"
    << "       1 with lines lw 2.5 dt 3 lc " << Rgb(colours::kUnoptimized) << " title "
    << GnuplotText("unoptimized program (distance " + Fixed(unopt, 2) + ")") << "\n";
  out.Plot("fitness", "Fitness per generation",
           "Best, mean and worst fitness of each generation (" + RunLabel(run) +
               "), divided by the unoptimized program's fitness (distance " + Fixed(unopt, 3) +
               " in run.json); generation 0 is the initial population. Dividing puts the paper's "
               "result on the same axis although its fitness units are unknown: its 1064 -> "
               "4070 is the dashed line at 3.83x. The right axis gives our distance in length "
               "units.",
           FitnessFigureCsv(rows, unopt), b.str());
}

void FitnessSeedsFigure(FigureWriter& out, const FiguresOptions& options) {
  std::vector<SeedRun> runs;
  for (const std::string& dir : options.runs) {
    SeedRun run;
    run.dir = dir;
    run.rows = ReadFitnessCsv(dir + "/fitness.csv");
    run.unoptimized_distance = ReadUnoptimizedDistance(ReadRunJson(dir), dir + "/run.json");
    runs.push_back(std::move(run));
  }
  const std::string csv = FitnessSeedsCsv(runs);
  double top = kPaperEvolved / kPaperUnoptimized;
  for (const SeedRun& run : runs) {
    for (const FitnessRow& r : run.rows) top = std::max(top, r.best / run.unoptimized_distance);
  }
  const int last = static_cast<int>(runs[0].rows.size()) - 1;
  const std::string n = std::to_string(runs.size());
  std::ostringstream b;
  b << "  set title " << GnuplotText("Best fitness per generation over " + n + " runs") << "\n"
    << "  set xlabel 'generation (0: initial population)'\n"
    << "  set ylabel 'best fitness / unoptimized fitness (×)'\n"
    << "  set xrange [-0.3:" << last + 0.3 << "]\n  set xtics 1\n"
    << "  set yrange [0:" << Fixed(top * kKeyRoom, 3) << "]\n"
    << "  set key top left\n"
    << "  plot 'fitness_seeds.csv' using 1:4:5 with filledcurves fc " << Rgb(colours::kEvolved)
    << " fs transparent solid 0.22 noborder title " << GnuplotText("min to max, " + n + " runs")
    << ", \\\n"
    << "       '' using 1:3 with linespoints lw 3 pt 7 ps 1.4 lc " << Rgb(colours::kEvolved)
    << " title 'median', \\\n"
    << "       " << kPaperEvolved / kPaperUnoptimized << " with lines lw 3 dt 2 lc "
    << Rgb(colours::kPaper) << " title 'paper: 4070 / 1064 = 3.83×', \\\n"
    << "       1 with lines lw 2.5 dt 3 lc " << Rgb(colours::kUnoptimized)
    << " title 'unoptimized program'\n";
  out.Plot("fitness_seeds", "Best fitness over several runs",
           "Best fitness of each generation over " + n +
               " 'hexgait evolve' runs (--runs), each divided by its own unoptimized "
               "fitness: the median and the band from the lowest to the highest run. The "
               "dashed line is the paper's 1064 -> 4070 (3.83x).",
           csv, b.str());
}

// Dashed vertical lines at the gait cycle boundaries, and a solid one at each fall.
std::string CycleLines(double period, double until) {
  std::ostringstream s;
  for (double t = period; t < until - 1e-9; t += period) {
    s << "  set arrow from " << t << ", graph 0 to " << t
      << ", graph 1 nohead dt 2 lw 1 lc rgb '#888888' back\n";
  }
  return s.str();
}

std::string FallLine(const RunResult& r, const char* colour, const std::string& label,
                     double label_y) {
  if (!r.fell) return "";
  std::ostringstream s;
  s << "  set arrow from " << r.fall_time << ", graph 0 to " << r.fall_time
    << ", graph 1 nohead lw 2.5 lc " << Rgb(colour) << " front\n"
    << "  set label " << GnuplotText(label) << " at " << r.fall_time << ", graph " << label_y
    << " offset 0.6,0 tc " << Rgb(colour) << " front\n";
  return s.str();
}

void GaitFigure(FigureWriter& out, const FigurePrograms& p, const std::vector<ProgramTrace>& traces,
                int cycles) {
  const double period = p.program.cycle_period;
  const double until = std::min(cycles * period, p.run.duration);
  // Whole cycles unless the run (--time) ends inside one: "first 0 gait cycles" said nothing.
  const double shown = until / period;
  const std::string shown_text = Fixed(shown, shown == std::round(shown) ? 0 : 1);
  const int legs = static_cast<int>(p.model.legs.size());
  std::ostringstream ytics;
  for (int leg = 0; leg < legs; ++leg) {
    std::string name = p.model.legs[leg].name;
    std::replace(name.begin(), name.end(), '_', ' ');
    ytics << (leg ? ", " : "") << GnuplotText(name) << ' ' << legs - leg;
  }
  std::ostringstream b;
  b << "  set multiplot layout 2,1 title "
    << GnuplotText("Gait diagram, first " + shown_text +
                   " gait cycles: coloured bars where a foot touches the ground,\n"
                   "grey where the motor program commands the leg to swing")
    << "\n"
    << "  set xrange [0:" << until << "]\n"
    << "  set yrange [0.4:" << legs + 0.6 << "]\n"
    << "  set ytics (" << ytics.str() << ")\n  set grid noytics\n"
    << "  set xlabel "
    << GnuplotQuote("time (time units; dashed: gait cycles of " + Fixed(period, 0) + ")")
    << "\n  unset key\n"
    << "  set style fill solid 1.0 noborder\n";
  for (const ProgramTrace& t : traces) {
    const char* colour = t.name == "unoptimized" ? colours::kUnoptimized : colours::kEvolved;
    b << "  unset arrow\n  unset label\n"
      << CycleLines(period, until)
      << (t.result.fell && t.result.fall_time < until ? FallLine(t.result, "#000000", "falls", 0.93)
                                                      : "")
      << "  set title " << GnuplotText(t.name + " program: " + FallPhrase(t.result)) << "\n"
      << "  plot 'gait.csv' using ((column(5)+column(6))/2):(strcol(2) eq 'swing' ? " << legs
      << "-column(3) : 1/0):((column(6)-column(5))/2):(0.45) with boxxyerror lc rgb '#d9d9d9', \\\n"
      << "       '' using ((column(5)+column(6))/2):(strcol(1) eq '" << t.name << "' ? " << legs
      << "-column(3) : 1/0):((column(6)-column(5))/2):(0.28) with boxxyerror lc " << Rgb(colour)
      << "\n";
  }
  b << "  unset multiplot\n  unset arrow\n  unset label\n";
  out.Plot(
      "gait", "Gait diagram (footfall pattern)",
      "For each leg, a bar while its foot touches the ground (lower than " +
          Fixed(kFootContactHeight, 3) + " length units), sampled every " +
          Fixed(traces[0].samples.size() > 1 ? traces[0].samples[1].time - traces[0].samples[0].time
                                             : 0,
                2) +
          " time units, for the first " + shown_text +
          " gait cycles; grey: the motor program's commanded swings (from the swing "
          "instruction to the leg's next one). The metachronal wave shows as swings "
          "stepping from rear to front on each side, the left side half a cycle after the "
          "right; short gaps inside a stance are the foot bouncing. "
          "Top: the unoptimized program; bottom: the evolved one (" +
          p.evolved_source + ").",
      GaitCsv(p.model, p.program, traces, until), b.str());
}

void BodyFigure(FigureWriter& out, const FiguresOptions& options, const FigurePrograms& p,
                const std::vector<ProgramTrace>& traces) {
  const RunResult& u = traces[0].result;
  const RunResult& e = traces[1].result;
  std::ostringstream b;
  const std::string falls = FallLine(u, colours::kUnoptimized, "unoptimized falls", 0.92) +
                            FallLine(e, colours::kEvolved, "evolved falls", 0.82);
  b << "  set multiplot layout 2,1 title 'Body height, pitch and roll over time'\n"
    << "  set xrange [0:" << p.run.duration << "]\n"
    << "  set key outside right top vertical\n"
    << "  set lmargin at screen 0.09\n  set rmargin at screen 0.74\n"
    << falls << "  set xlabel ''\n"
    << "  set ylabel \"body centre height\\n(length units)\"\n"
    << "  plot 'body.csv' using 1:2 with lines lw 2.5 lc " << Rgb(colours::kUnoptimized)
    << " title 'unoptimized', \\\n"
    << "       '' using 1:5 with lines lw 2.5 lc " << Rgb(colours::kEvolved) << " title 'evolved'\n"
    << "  set xlabel 'time (time units)'\n"
    << "  set ylabel 'angle (degrees)'\n"
    << "  plot 'body.csv' using 1:3 with lines lw 2.5 lc " << Rgb(colours::kUnoptimized)
    << " title 'unoptimized pitch', \\\n"
    << "       '' using 1:4 with lines lw 2.5 dt 2 lc " << Rgb(colours::kUnoptimized)
    << " title 'unoptimized roll', \\\n"
    << "       '' using 1:6 with lines lw 2.5 lc " << Rgb(colours::kEvolved)
    << " title 'evolved pitch', \\\n"
    << "       '' using 1:7 with lines lw 2.5 dt 2 lc " << Rgb(colours::kEvolved)
    << " title 'evolved roll'\n"
    << "  unset multiplot\n  unset arrow\n  unset label\n  unset lmargin\n  unset rmargin\n";
  out.Plot("body", "Body height, pitch and roll",
           "Top: height of the body centre (mean of the body particles). Bottom: pitch (the "
           "body's forward axis above the horizontal, nose up positive) and roll (left side up "
           "positive; 90 degrees is lying on its side). Vertical lines mark the falls: a body "
           "particle below " +
               Fixed(p.model.physics.fall_height, 2) + " or a tilt past " +
               Fixed(p.model.physics.fall_tilt_degrees, 0) +
               " degrees. Unoptimized: " + FallPhrase(u) + "; evolved: " + FallPhrase(e) + ".",
           BodyCsv(traces, options.curve_stride), b.str());
}

void PathFigure(FigureWriter& out, const FiguresOptions& options, const FigurePrograms& p,
                const std::vector<ProgramTrace>& traces) {
  double xlo = 0, xhi = 0, ymax = 1.0;
  for (const ProgramTrace& t : traces) {
    for (const TraceSample& s : t.samples) {
      xlo = std::min(xlo, s.centre.x());
      xhi = std::max(xhi, s.centre.x());
      ymax = std::max(ymax, std::fabs(s.centre.y()));
    }
  }
  std::ostringstream b;
  b << "  set title 'Top view of the body centre''s path'\n"
    << "  set xlabel 'x, the walking direction (length units)'\n"
    << "  set ylabel 'y (length units)'\n"
    << "  set size ratio -1\n"
    << "  set xrange [" << Fixed(xlo - 0.5, 2) << ":" << Fixed(xhi + 0.25 * (xhi - xlo) + 0.5, 2)
    << "]\n"
    << "  set yrange [" << Fixed(-1.2 * ymax - 0.3, 2) << ":" << Fixed(1.2 * ymax + 0.3, 2) << "]\n"
    << "  set key top left\n"
    << "  set label 'start' at 0,0 point pt 6 ps 2 lc rgb '#000000' offset -1,-1.2 front\n";
  for (const ProgramTrace& t : traces) {
    const TraceSample& last = t.samples.back();
    const char* colour = t.name == "unoptimized" ? colours::kUnoptimized : colours::kEvolved;
    b << "  set label " << GnuplotText("t = " + Fixed(last.time, 0)) << " at " << last.centre.x()
      << "," << last.centre.y() << " point pt 7 ps 1.8 lc " << Rgb(colour) << " offset 0.8,0.8 tc "
      << Rgb(colour) << " front\n";
    if (t.result.fell) {
      // The sample nearest the fall marks where it happened.
      const TraceSample* at = &t.samples[0];
      for (const TraceSample& s : t.samples) {
        if (std::fabs(s.time - t.result.fall_time) < std::fabs(at->time - t.result.fall_time)) {
          at = &s;
        }
      }
      b << "  set label 'falls' at " << at->centre.x() << "," << at->centre.y()
        << " point pt 2 ps 2.5 lw 2 lc " << Rgb(colour) << " offset 0.8,-1.2 tc " << Rgb(colour)
        << " front\n";
    }
  }
  b << "  plot 'path.csv' using 2:3 with lines lw 3 lc " << Rgb(colours::kUnoptimized)
    << " title 'unoptimized', \\\n"
    << "       '' using 4:5 with lines lw 3 lc " << Rgb(colours::kEvolved) << " title 'evolved'\n"
    << "  unset label\n  set size noratio\n";
  out.Plot("path", "Top view of the body centre's path",
           "The body centre seen from above over " + Fixed(p.run.duration, 0) +
               " time units, equal scales on both axes; the fitness is the distance along x. "
               "Circles: start and end; crosses: where a program falls.",
           PathCsv(traces, options.curve_stride), b.str());
}

// accuracy.csv from 'hexgait bench accuracy': stable rows with a positive error and time.
void AccuracyFigure(FigureWriter& out, const std::string& path) {
  const CsvTable table = CsvTable::Read(
      path, {"integrator", "program", "dt", "stable", "pos_error_cycle1", "wall_s_per_1000tu"});
  struct Row {
    std::string integrator, program;
    double dt, error, wall;
  };
  std::vector<Row> rows;
  for (size_t r = 0; r < table.rows(); ++r) {
    Row row{table.Text(r, "integrator"), table.Text(r, "program"), table.Number(r, "dt"),
            table.Number(r, "pos_error_cycle1"), table.Number(r, "wall_s_per_1000tu")};
    if (table.Bool(r, "stable") && row.error > 0 && row.wall > 0 && std::isfinite(row.error) &&
        std::isfinite(row.wall)) {
      rows.push_back(row);
    }
  }
  if (rows.empty()) {
    out.Skip("accuracy", path + " has no stable rows with a positive error");
    return;
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return std::tie(a.integrator, a.program, a.dt) < std::tie(b.integrator, b.program, b.dt);
  });
  std::ostringstream csv;
  csv << "integrator,program,dt,pos_error_cycle1,wall_s_per_1000tu\n";
  std::vector<std::pair<std::string, std::string>> series;
  for (const Row& r : rows) {
    // Streamed, not formatted into a fixed line: the names are the input file's, of any length.
    csv << r.integrator << ',' << r.program << ',' << Exact(r.dt) << ',' << Exact(r.error) << ','
        << Exact(r.wall) << '\n';
    if (series.empty() || series.back() != std::make_pair(r.integrator, r.program)) {
      series.emplace_back(r.integrator, r.program);
    }
  }
  std::map<std::string, int> integrator_index;
  for (const auto& s : series) integrator_index.emplace(s.first, integrator_index.size() + 1);
  std::map<std::string, int> program_dash;
  for (const auto& s : series) program_dash.emplace(s.second, program_dash.size() + 1);
  std::ostringstream b;
  b << "  set title 'Run time against accuracy (stable step sizes)'\n"
    << "  set logscale xy\n  set format x '10^{%L}'\n  set format y '10^{%L}'\n"
    << "  set xlabel 'position error after one gait cycle (length units)'\n"
    << "  set ylabel 'seconds of one core per 1000 time units'\n"
    << "  set key outside right top vertical\n"
    << "  plot ";
  for (size_t i = 0; i < series.size(); ++i) {
    const auto& [integrator, program] = series[i];
    b << (i ? ", \\\n       " : "") << "'accuracy.csv' using (strcol(1) eq "
      << GnuplotQuote(integrator) << " && strcol(2) eq " << GnuplotQuote(program)
      << " ? column(4) : 1/0):5 with linespoints lw 2.5 ps 1.3 pt " << 4 + 2 * (i % 4) << " lc "
      << Rgb(colours::kSeries[(integrator_index[integrator] - 1) % std::size(colours::kSeries)])
      << " dt " << program_dash[program] << " title "
      << GnuplotText(integrator + " (" + program + ")");
  }
  b << "\n  unset logscale\n  set format x\n  set format y\n";
  out.Plot("accuracy", "Run time against accuracy",
           "Work-precision diagram from " + path +
               " ('hexgait bench accuracy'): each point is one step size; x is the position "
               "error after one gait cycle against a reference solution, y the seconds of one "
               "core (the run thread's CPU time) per 1000 simulated time units. Lower left is "
               "better. Only stable runs are plotted.",
           csv.str(), b.str());
}

void StabilityFigure(FigureWriter& out, const std::string& path) {
  const CsvTable table = CsvTable::Read(
      path, {"integrator", "stiffness_multiplier", "dt", "stable", "max_energy_ratio"});
  if (table.rows() == 0) {
    out.Skip("stability", path + " has no rows");
    return;
  }
  std::vector<std::string> integrators;
  std::ostringstream csv;
  csv << "integrator,stiffness_multiplier,dt,stable,max_energy_ratio\n";
  double dt_lo = INFINITY, dt_hi = 0, k_lo = INFINITY, k_hi = 0;
  for (size_t r = 0; r < table.rows(); ++r) {
    const std::string& name = table.Text(r, "integrator");
    const double dt = table.Number(r, "dt"), k = table.Number(r, "stiffness_multiplier");
    if (!(dt > 0) || !(k > 0) || !std::isfinite(dt) || !std::isfinite(k)) {
      throw InputError(path + ": dt and stiffness_multiplier must be positive (row " +
                       std::to_string(r + 1) + ")");
    }
    dt_lo = std::min(dt_lo, dt);
    dt_hi = std::max(dt_hi, dt);
    k_lo = std::min(k_lo, k);
    k_hi = std::max(k_hi, k);
    if (std::find(integrators.begin(), integrators.end(), name) == integrators.end()) {
      integrators.push_back(name);
    }
    csv << name << ',' << Exact(k) << ',' << Exact(dt) << ',' << (table.Bool(r, "stable") ? 1 : 0)
        << ',' << Exact(table.Number(r, "max_energy_ratio")) << '\n';
  }
  const int n = static_cast<int>(integrators.size());
  const int columns = std::min(n, 3);
  const int rows = (n + columns - 1) / columns;
  std::ostringstream b;
  b << "  set multiplot layout " << rows << "," << columns
    << " title 'Stability map: step size against spring stiffness'\n"
    << "  set logscale xy\n"
    << "  set xlabel 'dt (time units)'\n  set ylabel 'stiffness multiplier'\n"
    // A third of a decade of room around the outermost points.
    << "  set xrange [" << dt_lo / 2.2 << ":" << dt_hi * 2.2 << "]\n"
    << "  set yrange [" << k_lo / 2.2 << ":" << k_hi * 2.2 << "]\n"
    << "  set key at screen 0.99, screen 0.99 right top horizontal\n";
  for (const std::string& name : integrators) {
    const std::string filter = "strcol(1) eq " + GnuplotQuote(name);
    b << "  set title " << GnuplotText(name) << "\n"
      << "  plot 'stability.csv' using (" << filter << " && column(4) == 1 ? column(3) : 1/0):2 "
      << "with points pt 5 ps 2.2 lc " << Rgb(colours::kStable) << " title 'stable', \\\n"
      << "       '' using (" << filter << " && column(4) == 0 ? column(3) : 1/0):2 "
      << "with points pt 5 ps 2.2 lc " << Rgb(colours::kDiverged) << " title 'diverged'\n"
      << "  unset key\n";
  }
  b << "  unset multiplot\n";
  out.Plot("stability", "Stability map",
           "From " + path +
               " ('hexgait bench stability'): for each integrator, each step size dt (x) and "
               "multiple of the springs' stiffness (y), green if the run stayed bounded, red "
               "if its energy grew without bound.",
           csv.str(), b.str());
}

}  // namespace

nlohmann::json MakeFigures(const FiguresOptions& options, const FigurePrograms& p,
                           const LogLine& log, const Progress& progress) {
  const auto start = Clock::now();
  if (options.gait_cycles < 1) throw InputError("--gait-cycles must be at least 1");
  // Read every input before any output exists.
  const RunRecord run = ReadRunJson(options.run_dir);
  ReadFitnessCsv(options.run_dir + "/fitness.csv");
  // What draws the figures, found before the simulations.
  CheckGnuplotFound();
  if (options.figure1) Png();
  AtomicDir dir(options.out_dir, kFiguresMarker, "--out");

  nlohmann::json manifest;
  manifest["hexgait_version"] = HEXGAIT_VERSION;
  manifest["run"] = options.run_dir;
  manifest["runs"] = options.runs;
  manifest["bench"] = options.bench_dir;
  manifest["figures"] = nlohmann::json::array();
  manifest["skipped"] = nlohmann::json::array();
  FigureWriter out(dir, manifest, log);

  if (options.figure1) {
    RenderFigure1(p.model, dir.File("figure1.png"), kFigureWidth, kFigureHeight,
                  options.figure1_camera);
    out.Record("figure1", "The creature at rest (the paper's Figure 1)",
               "The creature at rest: " + std::to_string(p.model.num_particles()) +
                   " particles (dots) and " + std::to_string(p.model.num_springs()) +
                   " springs (lines; motor springs in red) drawn over the polygons that cover "
                   "the body and legs, rendered off-screen as 'hexgait still' does.",
               {"figure1.png"});
    log("figure1.png  The creature at rest (the paper's Figure 1)");
  }
  FitnessFigure(out, options, run);
  if (!options.runs.empty()) FitnessSeedsFigure(out, options);

  // Both programs from rest, traced, with the run's settings.
  const auto sim_start = Clock::now();
  std::vector<ProgramTrace> traces;
  // Two runs: the first fills the first half of the progress, the second the rest.
  const auto half = [&](int which) -> Progress {
    if (!progress) return {};
    return [&progress, which](std::string_view stage, long long done, long long total) {
      progress(stage, which * total + done, 2 * total);
    };
  };
  traces.push_back(TraceProgram("unoptimized", p.model, p.program, p.unoptimized, p.run,
                                options.sample_interval, half(0)));
  traces.push_back(TraceProgram("evolved", p.model, p.program, p.evolved, p.run,
                                options.sample_interval, half(1)));
  for (const ProgramTrace& t : traces) {
    if (t.result.diverged) {
      throw InputError("the " + t.name +
                       " program's simulation diverged at t = " + Fixed(t.result.diverge_time, 2) +
                       ": " + t.result.diverge_reason + "; try a smaller --dt");
    }
  }
  const double sim_seconds = SecondsSince(sim_start);
  log("simulated both programs for " + Fixed(p.run.duration, 0) + " time units (" +
      Fixed(sim_seconds, 2) + " s)");
  GaitFigure(out, p, traces, options.gait_cycles);
  BodyFigure(out, options, p, traces);
  PathFigure(out, options, p, traces);

  for (const auto& [name, file] :
       {std::pair{"accuracy", "accuracy.csv"}, std::pair{"stability", "stability.csv"}}) {
    const std::string path = options.bench_dir + "/" + file;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      out.Skip(name, "no " + path + " (run 'hexgait bench " + name + "' to make it)");
    } else if (std::string(name) == "accuracy") {
      AccuracyFigure(out, path);
    } else {
      StabilityFigure(out, path);
    }
  }

  manifest["programs"]["unoptimized"] = ResultJson(traces[0].result);
  manifest["programs"]["evolved"] = ResultJson(traces[1].result);
  manifest["programs"]["evolved"]["genome"] = p.evolved_source;
  manifest["time"] = p.run.duration;
  manifest["dt"] = p.run.dt;
  manifest["integrator"] = IntegratorName(p.run.integrator);
  manifest["sample_interval"] = options.sample_interval;
  manifest["gait_cycles"] = options.gait_cycles;
  manifest["simulation_seconds"] = sim_seconds;
  manifest["wall_seconds"] = SecondsSince(start);
  WriteFileAtomically(dir.File(kFiguresManifest), manifest.dump(2) + "\n");
  dir.Commit();
  return manifest;
}

}  // namespace hexgait
