#include "report/endurance_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/csv.h"
#include "report/gnuplot.h"
#include "report/number_text.h"
#include "util/median.h"
#include "util/output.h"

namespace hexgait {
namespace {

// The path sample nearest the test's end (paths are sampled every path_interval from 0).
double TestEndSample(const EnduranceSettings& s) {
  const long long every = std::max(1LL, std::llround(s.path_interval / s.test.dt));
  const long long steps = std::llround(s.test.duration / s.test.dt);
  return static_cast<double>(steps / every * every) * s.test.dt;
}

// The runs of one condition whose gait is in `group`.
std::vector<const EnduranceRun*> RunsOf(const EnduranceResult& result,
                                        std::span<const EnduranceGait> gaits, int condition,
                                        const std::string& group) {
  std::vector<const EnduranceRun*> runs;
  for (const EnduranceRun& r : result.runs) {
    if (r.condition == condition && gaits[r.gait].group == group) runs.push_back(&r);
  }
  return runs;
}

std::vector<double> FallTimes(const std::vector<const EnduranceRun*>& runs) {
  std::vector<double> times;
  for (const EnduranceRun* r : runs) times.push_back(FallTime(r->result));
  return times;
}

int StandingAt(const std::vector<double>& fall_times, double t) {
  return static_cast<int>(
      std::count_if(fall_times.begin(), fall_times.end(), [t](double f) { return f > t; }));
}

// "18 of 20 (90%)".
std::string Share(int k, int n) {
  return std::to_string(k) + " of " + std::to_string(n) + " (" +
         Fixed(n > 0 ? 100.0 * k / n : 0.0, 0) + "%)";
}

std::string RunsCsv(std::span<const EnduranceGait> gaits, const EnduranceResult& result) {
  std::ostringstream csv;
  csv << "group,gait,condition,trial,push_time,horizon,fell,fall_time,diverged,standing_until,"
         "distance,end_time,mean_feet_on_ground,test_distance,test_fell\n";
  for (const EnduranceRun& r : result.runs) {
    const EnduranceCondition& c = result.conditions[r.condition];
    const RunResult& x = r.result;
    const double until = std::min(FallTime(x), c.horizon);
    csv << CsvText(gaits[r.gait].group) << ',' << CsvText(gaits[r.gait].name) << ',' << c.name
        << ',' << r.trial << ',' << Exact(r.push_time) << ',' << Exact(c.horizon) << ','
        << (x.fell ? 1 : 0) << ',' << (x.fell ? Exact(x.fall_time) : "") << ','
        << (x.diverged ? 1 : 0) << ',' << Exact(until) << ',' << Exact(x.distance) << ','
        << Exact(x.end_time) << ',' << Exact(x.mean_feet_on_ground) << ','
        << Exact(result.test[r.gait].distance) << ',' << (result.test[r.gait].fell ? 1 : 0) << '\n';
  }
  return csv.str();
}

std::string SurvivalCsv(std::span<const EnduranceGait> gaits, const EnduranceResult& result,
                        const std::vector<std::string>& groups) {
  std::ostringstream csv;
  csv << "condition,group,time,standing\n";
  for (int c = 0; c < static_cast<int>(result.conditions.size()); ++c) {
    for (const std::string& group : groups) {
      const auto curve =
          SurvivalCurve(FallTimes(RunsOf(result, gaits, c, group)), result.conditions[c].horizon);
      for (const auto& [t, standing] : curve) {
        csv << result.conditions[c].name << ',' << CsvText(group) << ',' << Exact(t) << ','
            << Exact(standing) << '\n';
      }
    }
  }
  return csv.str();
}

// One panel per condition, one curve per group; time on a log axis, so the test, 10x and 100x
// are equally far apart.
std::string SurvivalPlot(const EnduranceSettings& s, const EnduranceResult& result,
                         const std::vector<std::string>& groups) {
  const int k = static_cast<int>(result.conditions.size());
  const int columns = std::min(k, k == 4 ? 2 : 4);
  const int rows = (k + columns - 1) / columns;
  const double test = s.test.duration;
  const double x_lo = test / 100;  // a fall before this is drawn at it
  double x_hi = 0;
  for (const EnduranceCondition& c : result.conditions) x_hi = std::max(x_hi, c.horizon);
  std::ostringstream b;
  // The key is a row of screen-placed samples under the panels: a panel is too narrow for
  // the group names, and gnuplot drops a key that does not fit.
  const double step = 0.98 / std::max<size_t>(1, groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    const double x = 0.02 + step * static_cast<double>(g);
    b << "  set arrow " << 10 + g << " from screen " << Exact(x) << ", screen 0.035 to screen "
      << Exact(x + 0.035) << ", screen 0.035 nohead linewidth 2.5 linecolor "
      << Rgb(colours::kSeries[g % std::size(colours::kSeries)]) << "\n"
      << "  set label " << 10 + g << " " << GnuplotText(groups[g]) << " at screen "
      << Exact(x + 0.045) << ", screen 0.035 left font ',13'\n";
  }
  b << "  set multiplot layout " << rows << "," << columns
    << " margins 0.07, 0.98, 0.15, 0.9 spacing 0.07, 0.14"
    << " title 'Fraction of gaits still standing against time (open-loop control)'\n"
    << "  unset key\n"
    << "  set logscale x\n"
    << "  set xrange [" << Exact(x_lo) << ":" << Exact(x_hi) << "]\n"
    << "  set yrange [0:1.05]\n  set ytics 0,0.25,1\n"
    << "  set format x '10^{%T}'\n"
    << "  set xlabel 'time (test = " << Fixed(test, 0) << ")' offset 0,0.5\n"
    << "  set arrow 1 from " << Exact(test) << ", graph 0 to " << Exact(test)
    << ", graph 1 nohead dashtype 2 linewidth 1.5 linecolor rgb '#888888'\n";
  for (int c = 0; c < k; ++c) {
    const EnduranceCondition& cond = result.conditions[c];
    b << "  set title " << GnuplotText(cond.label) << " font ',13'\n  plot ";
    for (size_t g = 0; g < groups.size(); ++g) {
      const std::string filter = "strcol(1) eq " + GnuplotQuote(cond.name) + " && strcol(2) eq " +
                                 GnuplotQuote(CsvText(groups[g]));
      b << (g ? ", \\\n       " : "") << "'survival.csv' using (" << filter << " ? (column(3) < "
        << Exact(x_lo) << " ? " << Exact(x_lo)
        << " : column(3)) : 1/0):4 with steps linewidth 2.5 linecolor "
        << Rgb(colours::kSeries[g % std::size(colours::kSeries)]) << " notitle";
    }
    b << "\n";
    if (c == 0) {  // the key's samples are drawn once, with the first panel
      for (size_t g = 0; g < groups.size(); ++g) {
        b << "  unset arrow " << 10 + g << "\n  unset label " << 10 + g << "\n";
      }
    }
  }
  b << "  unset multiplot\n";
  return b.str();
}

std::string PathsCsv(std::span<const EnduranceGait> gaits, const EnduranceResult& result) {
  std::ostringstream csv;
  csv << "group,gait,time,x,y\n";
  for (size_t g = 0; g < result.paths.size(); ++g) {
    const EndurancePath& p = result.paths[g];
    for (size_t i = 0; i < p.x.size(); ++i) {
      csv << CsvText(gaits[g].group) << ',' << g << ',' << Exact(p.time[i]) << ',' << Exact(p.x[i])
          << ',' << Exact(p.y[i]) << '\n';
    }
  }
  return csv.str();
}

// Top views of the body centre's path, one panel per group, every gait from the origin: an
// open-loop gait that veers walks in circles.
std::string PathsPlot(const EnduranceSettings& s, std::span<const EnduranceGait> gaits,
                      const EnduranceResult& result, const std::vector<std::string>& groups) {
  double extent = 1;
  for (const EndurancePath& p : result.paths) {
    for (size_t i = 0; i < p.x.size(); ++i) {
      extent = std::max({extent, std::abs(p.x[i]), std::abs(p.y[i])});
    }
  }
  extent = std::ceil(extent * 1.05);
  const int k = static_cast<int>(groups.size());
  std::ostringstream b;
  b << "  set multiplot layout 1," << k
    << " margins 0.06, 0.99, 0.12, 0.88 spacing 0.04, 0.1 title "
    << GnuplotQuote(
           "Body centre seen from above, to t = " + Fixed(s.perturbed_factor * s.test.duration, 0) +
           " (" + Fixed(s.perturbed_factor, 0) +
           "x the test) or the fall; black dots: where the test ends")
    << "\n  unset key\n  set size ratio -1\n"
    << "  set xrange [" << -extent << ":" << extent << "]\n  set yrange [" << -extent << ":"
    << extent << "]\n  set xlabel 'x (walking direction)'\n  set ylabel 'y'\n";
  for (const std::string& group : groups) {
    if (group != groups.front()) b << "  unset ylabel\n";  // the panels share the y axis
    b << "  set title " << GnuplotText(group) << " font ',13'\n  plot ";
    int drawn = 0;
    for (size_t g = 0; g < gaits.size(); ++g) {
      if (gaits[g].group != group) continue;
      const char* colour = colours::kSeries[drawn % std::size(colours::kSeries)];
      const std::string filter = "column(2) == " + std::to_string(g);
      b << (drawn ? ", \\\n       " : "") << "'paths.csv' using (" << filter
        << " ? column(4) : 1/0):5 with lines linewidth 1.2 linecolor " << Rgb(colour)
        << ", '' using (" << filter << " && column(3) == " << Exact(TestEndSample(s))
        << " ? column(4) : 1/0):5 with points pointtype 7 pointsize 1 linecolor rgb 'black'";
      ++drawn;
    }
    b << "\n";
  }
  b << "  unset multiplot\n";
  return b.str();
}

std::string Tables(std::span<const EnduranceGait> gaits, const EnduranceSettings& s,
                   const EnduranceResult& result, const std::vector<std::string>& groups) {
  const double test = s.test.duration;
  const EnduranceCondition& none = result.conditions.front();
  const double perturbed = s.perturbed_factor * test;
  std::ostringstream md;
  md << "| gaits | runs | standing at t = " << Fixed(test, 0) << " (the test) | at "
     << Fixed(perturbed, 0) << " | at " << Fixed(none.horizon, 0)
     << " | median time to fall | median distance: in the test | per " << Fixed(test, 0)
     << " time units to the fall or the end | to t = " << Fixed(perturbed, 0)
     << " or the fall: along x | along the path | diverged (stops standing there; not a fall) "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& group : groups) {
    const auto runs = RunsOf(result, gaits, 0, group);
    const std::vector<double> falls = FallTimes(runs);
    const int n = static_cast<int>(runs.size());
    int diverged = 0;
    for (const EnduranceRun* r : runs) diverged += r->result.diverged ? 1 : 0;
    const double median_fall = Median(falls);
    std::vector<double> in_test, rate, along_x, along_path;
    for (const EnduranceRun* r : runs) {
      const EndurancePath& path = result.paths[r->gait];
      along_x.push_back(path.x.back() - path.x.front());
      along_path.push_back(path.length);
      in_test.push_back(result.test[r->gait].distance);
      rate.push_back(r->result.end_time > 0 ? r->result.distance / r->result.end_time * test : 0);
    }
    md << "| " << group << " | " << n << " | " << Share(StandingAt(falls, test), n) << " | "
       << Share(StandingAt(falls, perturbed), n) << " | "
       << Share(StandingAt(falls, none.horizon), n) << " | "
       << (std::isinf(median_fall) ? "over " + Fixed(none.horizon, 0) : Fixed(median_fall, 0))
       << " | " << Fixed(Median(in_test), 2) << " | " << Fixed(Median(rate), 2) << " | "
       << Fixed(Median(along_x), 1) << " | " << Fixed(Median(along_path), 1) << " | " << diverged
       << " |\n";
  }
  md << "\nStanding at t = " << Fixed(perturbed, 0) << " (" << Fixed(s.perturbed_factor, 0)
     << "x the test), by perturbation:\n\n| gaits |";
  for (const EnduranceCondition& c : result.conditions) md << ' ' << c.label << " |";
  md << "\n|---|";
  for (size_t c = 0; c < result.conditions.size(); ++c) md << "---|";
  md << '\n';
  for (const std::string& group : groups) {
    md << "| " << group << " |";
    for (int c = 0; c < static_cast<int>(result.conditions.size()); ++c) {
      const auto runs = RunsOf(result, gaits, c, group);
      const std::vector<double> falls = FallTimes(runs);
      int diverged = 0;
      for (const EnduranceRun* r : runs) diverged += r->result.diverged ? 1 : 0;
      md << ' ' << Share(StandingAt(falls, perturbed), static_cast<int>(falls.size()));
      if (diverged > 0) md << " (" << diverged << " diverged)";
      md << " |";
    }
    md << '\n';
  }
  return md.str();
}

}  // namespace

std::vector<std::string> EnduranceGroups(std::span<const EnduranceGait> gaits) {
  std::vector<std::string> groups;
  for (const EnduranceGait& g : gaits) {
    if (std::find(groups.begin(), groups.end(), g.group) == groups.end()) {
      groups.push_back(g.group);
    }
  }
  return groups;
}

std::string WriteEnduranceReport(const std::string& dir, std::span<const EnduranceGait> gaits,
                                 const EnduranceSettings& settings, const EnduranceResult& result) {
  const std::vector<std::string> groups = EnduranceGroups(gaits);
  WriteFileAtomically(dir + "/endurance.csv", RunsCsv(gaits, result));
  WriteFileAtomically(dir + "/survival.csv", SurvivalCsv(gaits, result, groups));
  WriteFileAtomically(dir + "/survival.gp",
                      GnuplotScript("survival", "survival of gaits under perturbations",
                                    SurvivalPlot(settings, result, groups), "hexgait endurance"));
  RunGnuplot(dir, "survival.gp");
  WriteFileAtomically(dir + "/paths.csv", PathsCsv(gaits, result));
  WriteFileAtomically(
      dir + "/paths.gp",
      GnuplotScript("paths", "body-centre paths of the unperturbed gaits",
                    PathsPlot(settings, gaits, result, groups), "hexgait endurance"));
  RunGnuplot(dir, "paths.gp");
  const std::string tables = Tables(gaits, settings, result, groups);
  WriteFileAtomically(dir + "/table.md", tables);
  return tables;
}

}  // namespace hexgait
