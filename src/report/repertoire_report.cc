#include "report/repertoire_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ga/archive_table.h"
#include "ga/map_elites_checkpoint.h"
#include "report/gnuplot.h"
#include "report/number_text.h"
#include "util/output.h"

namespace hexgait {
namespace {

// "right_rear" -> "RR", "right_rear+left_rear" -> "RR+LR": short enough for a caption.
std::string Initials(const std::string& name) {
  std::string out;
  bool start = true;
  for (char c : name) {
    if (c == '_' || c == ' ') {
      start = true;
    } else if (c == '+') {
      out += '+';
      start = true;
    } else if (start) {
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      start = false;
    }
  }
  return out;
}

// Where a cell sits on the map: the axes are split in two halves, the first half nested along
// x (its first axis outermost), the second along y.
void MapPosition(const Archive& archive, int cell, int* x, int* y) {
  std::vector<int> bins(static_cast<size_t>(archive.dims()));
  archive.BinsOf(cell, bins.data());
  const int x_axes = (archive.dims() + 1) / 2;
  *x = *y = 0;
  for (int d = 0; d < archive.dims(); ++d) {
    int& coordinate = d < x_axes ? *x : *y;
    coordinate = coordinate * archive.bins() + bins[static_cast<size_t>(d)];
  }
}

int Power(int base, int exponent) {
  int out = 1;
  for (int i = 0; i < exponent; ++i) out *= base;
  return out;
}

// ga/archive_table.h's table, doubles written to round-trip.
std::string ArchiveCsv(const CreatureModel& model, const BehaviourDescriptor& descriptor,
                       const Archive& archive, double gene_length_step) {
  const std::vector<ArchiveColumn> table =
      ArchiveTable(model, descriptor, archive, gene_length_step);
  std::ostringstream csv;
  for (size_t c = 0; c < table.size(); ++c) csv << (c ? "," : "") << table[c].name;
  csv << '\n';
  const size_t rows = table.front().ints.size();
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < table.size(); ++c) {
      if (c) csv << ',';
      if (table[c].integer) {
        csv << table[c].ints[r];
      } else {
        csv << Exact(table[c].reals[r]);
      }
    }
    csv << '\n';
  }
  return csv.str();
}

std::string ProgressCsv(const std::vector<RepertoireMethod>& methods, long long cells) {
  std::ostringstream csv;
  csv << "method,evaluations,filled,coverage,qd_score,best,diverged\n";
  for (size_t m = 0; m < methods.size(); ++m) {
    for (const ArchiveStats& s : methods[m].history) {
      csv << m << ',' << s.evaluations << ',' << s.filled << ','
          << Exact(static_cast<double>(s.filled) / static_cast<double>(cells)) << ','
          << Exact(s.qd_score) << ',' << Exact(s.best) << ',' << s.diverged << '\n';
    }
  }
  return csv.str();
}

// Three panels against evaluations: cells filled, QD-score, farthest standing gait.
std::string ProgressPlot(const std::vector<RepertoireMethod>& methods) {
  // About five x tics, at 1, 2 or 5 times a power of ten thousand evaluations: the panels are
  // narrow, and gnuplot's own choice crowds their labels.
  long long most = 1;
  for (const RepertoireMethod& m : methods) most = std::max(most, m.evaluations);
  const double rough = static_cast<double>(most) / 1000 / 5;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double tic = rough / power < 2 ? power : rough / power < 5 ? 2 * power : 5 * power;
  std::ostringstream b;
  // The right margin leaves room for the last x label, centred on the panel's edge.
  const std::string title = methods.size() > 1 ? "The repertoire growing: " + methods.front().name +
                                                     " against the same budget"
                                               : "The repertoire growing: " + methods.front().name;
  b << "  set multiplot layout 1,3 margins 0.07, 0.96, 0.2, 0.86 spacing 0.07, 0.1 title "
    << GnuplotQuote(title) << "\n  unset key\n  set xlabel 'evaluations (thousands)'\n  set xtics "
    << Exact(tic) << "\n";
  // The key, once, as a row of screen-placed samples under the panels.
  const double step = 0.96 / static_cast<double>(methods.size());
  for (size_t m = 0; m < methods.size(); ++m) {
    const double x = 0.04 + step * static_cast<double>(m);
    b << "  set arrow " << 10 + m << " from screen " << Exact(x) << ", screen 0.05 to screen "
      << Exact(x + 0.035) << ", screen 0.05 nohead linewidth 3 linecolor "
      << Rgb(colours::kSeries[m % std::size(colours::kSeries)]) << "\n  set label " << 10 + m << " "
      << GnuplotText(methods[m].name) << " at screen " << Exact(x + 0.045)
      << ", screen 0.05 left font ',13'\n";
  }
  const char* titles[] = {"distinct gaits (cells filled)", "QD-score (sum of distances)",
                          "farthest standing gait"};
  const int columns[] = {3, 5, 6};
  for (int panel = 0; panel < 3; ++panel) {
    b << "  set title '" << titles[panel] << "' font ',13'\n  plot ";
    for (size_t m = 0; m < methods.size(); ++m) {
      b << (m ? ", \\\n       " : "") << "'progress.csv' using (column(1) == " << m
        << " ? column(2) / 1000 : 1/0):" << columns[panel] << " with lines linewidth 2.5 linecolor "
        << Rgb(colours::kSeries[m % std::size(colours::kSeries)]);
    }
    b << "\n";
    if (panel == 0) {
      for (size_t m = 0; m < methods.size(); ++m) {
        b << "  unset arrow " << 10 + m << "\n  unset label " << 10 + m << "\n";
      }
    }
  }
  b << "  unset multiplot\n";
  return b.str();
}

std::string MapCsv(const Archive& archive, const std::vector<int>& showcase) {
  std::ostringstream csv;
  csv << "x,y,distance,cell,showcase\n";
  for (int cell : archive.filled()) {
    int x = 0, y = 0;
    MapPosition(archive, cell, &x, &y);
    const auto it = std::find(showcase.begin(), showcase.end(), cell);
    csv << x << ',' << y << ',' << Exact(archive.at(cell)->fitness) << ',' << cell << ','
        << (it == showcase.end() ? 0 : 1 + (it - showcase.begin())) << '\n';
  }
  return csv.str();
}

// The nested grid: each cell a square coloured by distance; heavy lines between the outermost
// axes' bins, light ones between the next; the showcase's elites numbered.
std::string MapPlot(const CreatureModel& model, const BehaviourDescriptor& descriptor,
                    const Archive& archive, const std::vector<int>& showcase) {
  const std::vector<std::string> axes = descriptor.axes(model);
  const int dims = archive.dims(), bins = archive.bins();
  const int x_axes = (dims + 1) / 2, y_axes = dims - x_axes;
  const int width = Power(bins, x_axes), height = Power(bins, std::max(1, y_axes));
  const auto axis_label = [&](int first, int count) {
    std::string text;
    for (int d = first; d < first + count; ++d) text += (d > first ? " / " : "") + axes[d];
    return text + (count > 1 ? " (outer to inner)" : "");
  };
  std::ostringstream b;
  b << "  set title "
    << GnuplotQuote(descriptor.name + " map: " + std::to_string(archive.filled().size()) + " of " +
                    std::to_string(archive.cells()) +
                    " cells hold a standing gait; colour: distance walked")
    << "\n  unset key\n  unset grid\n  set size ratio -1\n"
    << "  set xrange [0:" << width << "]\n  set yrange [0:" << height << "]\n"
    << "  set xlabel " << GnuplotText(axis_label(0, x_axes) + ": duty-factor bins") << "\n"
    << "  set ylabel "
    << GnuplotText(y_axes > 0 ? axis_label(x_axes, y_axes) + ": duty-factor bins" : "")
    << "\n  set cblabel 'distance walked'\n"
    // No white at the low end: every filled cell must show against the empty ones.
    << "  set palette defined (0 '#f6d55c', 0.35 '#7ccba2', 0.7 '#2f8fb5', 1 '#1d3461')\n";
  // Tics at the outermost bins' centres, labelled with their duty-factor range.
  const int outer_x = width / bins, outer_y = height / bins;
  b << "  set xtics (";
  for (int i = 0; i < bins; ++i) {
    b << (i ? ", " : "") << "'" << Fixed(static_cast<double>(i) / bins, 1) << "-"
      << Fixed(static_cast<double>(i + 1) / bins, 1) << "' " << Exact((i + 0.5) * outer_x);
  }
  b << ") scale 0\n  set ytics (";
  for (int i = 0; i < bins; ++i) {
    b << (i ? ", " : "") << "'" << Fixed(static_cast<double>(i) / bins, 1) << "-"
      << Fixed(static_cast<double>(i + 1) / bins, 1) << "' " << Exact((i + 0.5) * outer_y);
  }
  b << ") scale 0\n";
  int arrow = 1;
  const auto lines = [&](int extent, int spacing, int other, bool vertical, double lw,
                         const char* colour) {
    for (int at = spacing; at < extent; at += spacing) {
      b << "  set arrow " << arrow++ << " from " << (vertical ? at : 0) << ", "
        << (vertical ? 0 : at) << " to " << (vertical ? at : other) << ", "
        << (vertical ? other : at) << " nohead front linewidth " << Exact(lw) << " linecolor rgb '"
        << colour << "'\n";
    }
  };
  if (outer_x > 1)
    lines(width, outer_x / bins > 0 ? outer_x / bins : 1, height, true, 0.4, "#dddddd");
  if (outer_y > 1)
    lines(height, outer_y / bins > 0 ? outer_y / bins : 1, width, false, 0.4, "#dddddd");
  lines(width, outer_x, height, true, 1.6, "#555555");
  lines(height, outer_y, width, false, 1.6, "#555555");
  for (size_t i = 0; i < showcase.size(); ++i) {
    int x = 0, y = 0;
    MapPosition(archive, showcase[i], &x, &y);
    b << "  set label " << i + 1 << " '" << i + 1 << "' at " << Exact(x + 0.5) << ", "
      << Exact(y + 0.5) << " center front font ',14' textcolor rgb '#c0392b' offset 0.9,0.9\n";
  }
  b << "  plot 'map.csv' using ($1 + 0.5):($2 + 0.5):(0.5):(0.5):3 with boxxyerror fillstyle "
       "solid noborder linecolor palette, \\\n"
       "       '' using ($5 > 0 ? $1 + 0.5 : 1/0):($2 + 0.5) with points pointtype 6 pointsize "
       "1.6 linewidth 2 linecolor rgb '#c0392b'\n";
  return b.str();
}

std::string Tables(const CreatureModel& model, const BehaviourDescriptor& descriptor,
                   const std::vector<RepertoireMethod>& methods, const std::vector<int>& showcase) {
  std::ostringstream md;
  const Archive& archive = *methods.front().archive;
  md << "| method | evaluations | diverged | standing gaits found: distinct cells | of "
     << archive.cells()
     << " | QD-score | farthest standing gait | best fitness of any evaluation | wall time |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const RepertoireMethod& m : methods) {
    const int filled = static_cast<int>(m.archive->filled().size());
    const Elite* best = m.archive->Best();
    md << "| " << m.name << " | " << m.evaluations << " | " << m.diverged << " | " << filled
       << " | " << Fixed(100.0 * filled / static_cast<double>(archive.cells()), 1) << "% | "
       << Fixed(m.archive->QdScore(), 1) << " | " << (best ? Fixed(best->fitness, 3) : "–") << " | "
       << (std::isfinite(m.best_fitness) ? Fixed(m.best_fitness, 3) : "–") << " | "
       << Fixed(m.seconds / 60, 1) << " min |\n";
  }
  md << "\nThe elites in the movie grid (numbered on the map):\n\n| # | cell | " << descriptor.name
     << " (";
  const std::vector<std::string> axes = descriptor.axes(model);
  for (size_t d = 0; d < axes.size(); ++d) md << (d ? " " : "") << Initials(axes[d]);
  md << ") | distance | found at evaluation |\n|---|---|---|---|---|\n";
  for (size_t i = 0; i < showcase.size(); ++i) {
    const Elite& e = *archive.at(showcase[i]);
    md << "| " << i + 1 << " | " << showcase[i] << " |";
    for (double v : BehaviourOf(model, descriptor, e.result)) md << ' ' << Fixed(v, 2);
    md << " | " << Fixed(e.fitness, 3) << " | " << e.found_at << " |\n";
  }
  return md.str();
}

}  // namespace

std::vector<std::string> BehaviourLines(const CreatureModel& model,
                                        const BehaviourDescriptor& descriptor,
                                        const RunResult& result) {
  const std::vector<std::string> axes = descriptor.axes(model);
  const std::vector<double> b = BehaviourOf(model, descriptor, result);
  std::vector<std::string> lines;
  const size_t per_line = axes.size() > 4 ? (axes.size() + 1) / 2 : axes.size();
  for (size_t d = 0; d < axes.size(); ++d) {
    if (d % per_line == 0) lines.emplace_back(d == 0 ? descriptor.name + ": " : "");
    if (d == per_line) lines.back().assign(descriptor.name.size() + 2, ' ');
    lines.back() += (d % per_line ? "  " : "") + Initials(axes[d]) + " " + Fixed(b[d], 2);
  }
  return lines;
}

std::string WriteRepertoireReport(const std::string& dir, const CreatureModel& model,
                                  double gene_length_step, const BehaviourDescriptor& descriptor,
                                  const std::vector<RepertoireMethod>& methods,
                                  const std::vector<int>& showcase) {
  const Archive& archive = *methods.front().archive;
  WriteFileAtomically(dir + "/archive.csv",
                      ArchiveCsv(model, descriptor, archive, gene_length_step));
  WriteFileAtomically(dir + "/progress.csv", ProgressCsv(methods, archive.cells()));
  WriteFileAtomically(dir + "/progress.gp",
                      GnuplotScript("progress", "coverage and QD-score against evaluations",
                                    ProgressPlot(methods), "hexgait repertoire"));
  RunGnuplot(dir, "progress.gp");
  WriteFileAtomically(dir + "/map.csv", MapCsv(archive, showcase));
  WriteFileAtomically(dir + "/map.gp", GnuplotScript("map", "the repertoire's map",
                                                     MapPlot(model, descriptor, archive, showcase),
                                                     "hexgait repertoire"));
  RunGnuplot(dir, "map.gp");
  const std::string tables = Tables(model, descriptor, methods, showcase);
  WriteFileAtomically(dir + "/table.md", tables);
  return tables;
}

}  // namespace hexgait
