// 'hexgait report': one static HTML page with the whole experiment (movies, figures, the
// paper-versus-ours table, parameters and timings), in a folder that holds copies of every
// file it shows, so it opens from disk and can be attached to a report as it is.
#pragma once

#include <string>

namespace hexgait {

struct ReportOptions {
  std::string run_dir = "out/run";  // 'hexgait evolve' folder (run.json)
  std::string movies_dir = "out";   // unoptimized/evolved/comparison.mp4, unoptimized/evolved.html
  std::string figures_dir = "out/figures";  // 'hexgait figures' folder (figures.json)
  std::string out_dir = "out/report";       // replaced whole
  // A finished 'hexgait repertoire' folder, for the page's repertoire section; empty: none.
  std::string repertoire_dir;
  // A finished 'hexgait adapt' folder, for the page's section on adapting to damage; empty: none.
  std::string adapt_dir;
};

// Writes out_dir/index.html and the copies; returns the number of figures on the page.
// Throws InputError naming a missing input and the command that makes it.
int MakeReport(const ReportOptions& options);

inline constexpr const char* kReportMarker = ".hexgait-report";
// What the page shows of a repertoire folder (grid.mp4 only when it was rendered).
inline constexpr const char* kReportRepertoireFiles[] = {
    "repertoire.json", "map.png", "map.svg", "progress.png", "progress.svg", "archive.csv"};
// What the page shows of an adapt folder (adapt.mp4 too when it was rendered).
inline constexpr const char* kReportAdaptFiles[] = {"adapt.json", "adapt.png", "adapt.svg",
                                                    "trials.csv", "adapted.genome"};
// The movies the page shows, in order, and the command that makes them.
inline constexpr const char* kReportMovies[] = {"unoptimized.mp4", "evolved.mp4", "comparison.mp4"};
// The browser replays of the same two programs, also made by 'hexgait movie', embedded beside
// the movies (the page itself stays script-free: each replay runs in its own frame).
inline constexpr const char* kReportReplays[] = {"unoptimized.html", "evolved.html"};

}  // namespace hexgait
