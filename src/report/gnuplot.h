// Drives gnuplot: every figure is a self-contained script next to its CSV, written so that
// `cd FOLDER && gnuplot NAME.gp` redraws the PNG and SVG; RunGnuplot does exactly that.
#pragma once

#include <string>

namespace hexgait {

// The report size every figure shares (pixels for the PNG, the SVG's nominal size).
inline constexpr int kFigureWidth = 1200;
inline constexpr int kFigureHeight = 800;

// One palette for every figure, so a program has the same colour everywhere.
namespace colours {
inline constexpr const char* kUnoptimized = "#c0392b";  // red
inline constexpr const char* kEvolved = "#1f6fb4";      // blue
inline constexpr const char* kMean = "#e08a00";         // orange
inline constexpr const char* kWorst = "#7d3c98";        // purple
inline constexpr const char* kPaper = "#2e7d32";        // green: the paper's numbers
inline constexpr const char* kStable = "#2e9e4f";
inline constexpr const char* kDiverged = "#d0312d";
// One colour per integrator in the accuracy figure, in order of first appearance.
inline constexpr const char* kSeries[] = {"#1f6fb4", "#e08a00", "#2e7d32", "#7d3c98",
                                          "#c0392b", "#00838f", "#6d4c41", "#546e7a"};
}  // namespace colours

// The script around a figure's plot commands `body`: shared style, then the body once for the
// PNG terminal (pngcairo) and once for the SVG one, writing NAME.png and NAME.svg.
// `command` names what wrote it, in its header comment.
std::string GnuplotScript(const std::string& name, const std::string& description,
                          const std::string& body, const std::string& command = "hexgait figures");

// A string as a gnuplot double-quoted literal; '\n' becomes a line break. For data (file
// names, strcol comparisons).
std::string GnuplotQuote(const std::string& text);
// The same for text shown in a figure: enhanced-text markup characters (_ ^ @ & { }) print
// as themselves, so "semi_implicit_euler" is not typeset with a subscript.
std::string GnuplotText(const std::string& text);

// A colour as a gnuplot colour spec: rgb '#1f6fb4'.
inline std::string Rgb(const char* colour) {
  return std::string("rgb '") + colour + "'";
}

// Throws SystemError naming the Debian package unless an executable gnuplot is on PATH: what
// will draw figures calls it before its work, not when the first figure is due.
void CheckGnuplotFound();
// Runs `gnuplot SCRIPT` in `folder` (posix_spawnp: no shell, PATH lookup). Throws SystemError
// when gnuplot is missing (as CheckGnuplotFound) or fails (with its first error line).
void RunGnuplot(const std::string& folder, const std::string& script);

}  // namespace hexgait
