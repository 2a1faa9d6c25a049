#include "report/adapt_report.h"

#include <algorithm>
#include <sstream>

#include "report/gnuplot.h"
#include "report/number_text.h"
#include "util/output.h"

namespace hexgait {

void WriteAdaptFigure(const std::string& dir, const AdaptFigureData& d) {
  std::ostringstream csv;
  csv << "trial,distance,best\n";
  for (size_t i = 0; i < d.trial_distance.size(); ++i) {
    csv << i + 1 << ',' << Exact(d.trial_distance[i]) << ',' << Exact(d.best_so_far[i]) << '\n';
  }
  WriteFileAtomically(dir + "/adapt.csv", csv.str());
  const size_t trials = d.trial_distance.size();
  std::ostringstream b;
  b << "  set title "
    << GnuplotText("Adapting to " + d.damage + " in " + std::to_string(trials) +
                   (trials == 1 ? " trial" : " trials"))
    // An empty second line under the x label: without it the key below touches the label.
    << "\n  set xlabel \"trial\\n\"\n  set ylabel 'distance walked on the damaged creature'\n"
    << "  set xrange [0.5:" << Exact(std::max<double>(trials, 2) + 0.5) << "]\n"
    << "  set xtics 1\n  set key below\n"
    // Room above the highest line: the best elite's, often the autoscaled top, would lie on the
    // frame and not be seen.
    << "  set offsets 0, 0, graph 0.05, 0\n"
    << "  plot " << Exact(d.best_elite_on_damaged)
    << " with lines dashtype 2 linewidth 2 linecolor " << Rgb(colours::kStable)
    << " title 'best elite on the damaged creature (all tried)', \\\n       "
    << Exact(d.intact_best_on_damaged) << " with lines dashtype 3 linewidth 2 linecolor "
    << Rgb(colours::kDiverged) << " title 'intact best gait on the damaged creature', \\\n"
    << "       'adapt.csv' using 1:3 with steps linewidth 2.5 linecolor "
    << Rgb(colours::kSeries[0]) << " title 'best so far', \\\n"
    << "       'adapt.csv' using 1:2 with points pointtype 7 pointsize 1.4 linecolor "
    << Rgb(colours::kSeries[1]) << " title 'trial'\n";
  WriteFileAtomically(dir + "/adapt.gp",
                      GnuplotScript("adapt", "distance per trial while adapting to a damage",
                                    b.str(), "hexgait adapt"));
  RunGnuplot(dir, "adapt.gp");
}

}  // namespace hexgait
