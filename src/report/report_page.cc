#include "report/report_page.h"
#include "report/number_text.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "record/adapt_record.h"
#include "record/repertoire_record.h"
#include "record/run_record.h"
#include "render/leg_colours.h"
#include "report/figures.h"
#include "util/error.h"
#include "util/html_text.h"
#include "util/json_file.h"
#include "util/output.h"

namespace hexgait {
namespace fs = std::filesystem;
namespace {

std::string Html(const std::string& text) {
  return HtmlEscape(text);
}

// A JSON value as table text: numbers with up to 6 significant digits, strings unquoted.
std::string Cell(const nlohmann::json& v) {
  if (v.is_null()) return "–";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char text[48];
    std::snprintf(text, sizeof text, "%.6g", v.get<double>());
    return text;
  }
  return v.dump();
}

// A record's field as Cell writes the JSON value: integers whole, others with up to 6 significant
// digits, an empty string as a missing value.
std::string Cell(double v) {
  return Cell(nlohmann::json(v));
}
std::string Cell(long long v) {
  return std::to_string(v);
}
std::string Cell(int v) {
  return std::to_string(v);
}
std::string Cell(uint64_t v) {
  return std::to_string(v);
}
std::string Cell(const std::string& v) {
  return v.empty() ? "–" : v;
}

// A member of `j`, or null when absent.
nlohmann::json Get(const nlohmann::json& j, const std::string& key) {
  return j.is_object() && j.contains(key) ? j[key] : nlohmann::json(nullptr);
}

void RequireFile(const std::string& path, const std::string& command) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw InputError("no " + path + ": run '" + command + "' first");
  }
}

void Copy(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError("cannot copy " + from + " to " + to + ": " + ec.message());
}

const nlohmann::json& Field(const nlohmann::json& j, const std::string& key,
                            const std::string& source) {
  if (!j.is_object() || !j.contains(key)) throw InputError(source + ": no field '" + key + "'");
  return j[key];
}

std::string FallText(const OutcomeRecord& result) {
  if (!result.fell) return "does not fall";
  return "falls in cycle " +
         (result.fall_cycle ? Cell(*result.fall_cycle) : Cell(nlohmann::json())) +
         " (t = " + Fixed(result.fall_time.value_or(0.0), 0) + ")";
}

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", "Helvetica Neue", Arial, sans-serif; margin: 0 auto;
       max-width: 1280px; padding: 1.5em 2em 4em; color: #222; line-height: 1.45; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { border-bottom: 2px solid #ddd; padding-bottom: 0.2em; margin-top: 2em; }
.lead { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.8em 0; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.7em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.movies { display: grid; grid-template-columns: 1fr 1fr; gap: 1em; }
.movies figure.wide { grid-column: 1 / span 2; }
figure { margin: 0 0 1.5em; }
video, figure img { width: 100%; height: auto; border: 1px solid #ccc; background: #fff; }
iframe.replay { width: 100%; aspect-ratio: 8 / 7; border: 1px solid #ccc; display: block; }
figcaption { color: #444; font-size: 0.95em; margin-top: 0.3em; }
figcaption a { color: #1f6fb4; }
.note { color: #666; font-size: 0.9em; }
)";

// Adapting to damage: what the damage did to the intact best gait, how many trials the
// repertoire needed, against the comparisons; the figure and the side-by-side movie.
void AdaptSection(std::ostringstream& h, const AdaptSummary& a, bool movie) {
  const double best = a.best_elite;
  const auto share = [&](double v) { return best > 0 ? Fixed(100 * v / best, 0) + "%" : "–"; };
  const double adapted = a.adapted;
  const double intact = a.intact_best;
  const double random = a.random_best;
  const double ga = a.ga_best;
  const int trials = a.trials;
  const std::string n = trials == 1 ? "1 trial" : std::to_string(trials) + " trials";
  const std::string random_elites =
      trials == 1 ? "1 random elite" : std::to_string(trials) + " random elites";
  h << "<h2 id=\"adapt\">Adapting to damage (Intelligent Trial and Error)</h2>\n"
    << "<p>The creature damaged (<code>" << Html(a.damage)
    << "</code>) tried gaits from the repertoire, chosen by a Gaussian process whose prior is "
       "the repertoire's map of distances (Cully et al., Nature 2015), until the best trial "
       "reached "
    << Fixed(100 * a.stop_fraction, 0) << "% of the best prediction: " << n
    << ". <code>hexgait adapt</code> wrote everything in this section.</p>\n<table>\n"
    << "<tr><th>on the damaged creature</th><th>distance in " << Fixed(a.time, 0)
    << " time units</th><th>of the best elite</th></tr>\n"
    << "<tr><th>the intact best gait, kept</th><td class=\"num\">" << Fixed(intact, 2)
    << "</td><td class=\"num\">" << share(intact) << "</td></tr>\n"
    << "<tr><th>the adapted gait, after " << n << "</th><td class=\"num\">" << Fixed(adapted, 2)
    << "</td><td class=\"num\">" << share(adapted) << "</td></tr>\n"
    << "<tr><th>the best of " << random_elites << "</th><td class=\"num\">" << Fixed(random, 2)
    << "</td><td class=\"num\">" << share(random) << "</td></tr>\n"
    << "<tr><th>the paper's GA from the intact best, " << a.ga_evaluations
    << " evaluations</th><td class=\"num\">" << Fixed(ga, 2) << "</td><td class=\"num\">"
    << share(ga) << "</td></tr>\n"
    << "<tr><th>the best elite (every one of " << a.elites << " run once)</th><td class=\"num\">"
    << Fixed(best, 2) << "</td><td class=\"num\">100%</td></tr>\n"
    << "</table>\n<figure><img src=\"adapt/adapt.png\" alt=\"distance per trial\">"
    << "<figcaption>Each trial's distance and the best so far, with the intact best gait and the "
       "best elite on the damaged creature as lines. <a href=\"adapt/adapt.svg\">SVG</a>, "
       "<a href=\"adapt/trials.csv\">trials.csv</a>, <a href=\"adapt/adapted.genome\">"
       "adapted.genome</a></figcaption></figure>\n";
  if (movie) {
    h << "<figure class=\"wide\"><video controls preload=\"auto\" src=\"adapt/adapt.mp4\">"
         "</video><figcaption>The damaged creature with the intact best gait (top) and the "
         "adapted gait (bottom), on one clock. <a href=\"adapt/adapt.mp4\">adapt.mp4</a>"
         "</figcaption></figure>\n";
  }
}

// MAP-Elites' repertoire: the comparison with the GA, the map, the movie grid and its elites,
// and how the archive grew.
void RepertoireSection(std::ostringstream& h, const RepertoireRecord& r) {
  h << "<h2 id=\"repertoire\">A repertoire of gaits (MAP-Elites)</h2>\n"
    << "<p>Beyond the paper: MAP-Elites kept, for each combination of the six legs' duty factors "
       "(the fraction of the walk each foot is on the ground, "
    << Html(Cell(r.bins))
    << " bins per leg), the farthest-walking genome that stands the whole test. "
       "<code>hexgait repertoire</code> wrote everything in this section.</p>\n<table>\n"
    << "<tr><th>method</th><th>evaluations</th><th>distinct gaits (cells)</th><th>QD-score</th>"
       "<th>farthest standing gait</th><th>wall time</th></tr>\n";
  for (const RepertoireMethodRecord& m : r.methods) {
    h << "<tr><td>" << Html(Cell(m.name)) << "</td><td class=\"num\">" << Html(Cell(m.evaluations))
      << "</td><td class=\"num\">" << Html(Cell(m.filled)) << " of " << Html(Cell(r.cells))
      << "</td><td class=\"num\">" << Html(Cell(m.qd_score)) << "</td><td class=\"num\">"
      << Html(Cell(m.best_standing)) << "</td><td class=\"num\">" << Html(Cell(m.seconds))
      << " s</td></tr>\n";
  }
  h << "</table>\n<figure id=\"figure-repertoire-map\"><img src=\"repertoire/map.png\" "
       "alt=\"map of the repertoire\"><figcaption><b>The map.</b> The six-dimensional grid of "
       "duty factors drawn as nested squares (right legs across, left legs up; outer to inner: "
       "rear, middle, front); each coloured square is one gait, its colour the distance it "
       "walks. Numbers: the elites in the movie. <a href=\"repertoire/map.svg\">map.svg</a> "
       "<a href=\"repertoire/archive.csv\">archive.csv</a></figcaption></figure>\n";
  if (r.movie) {
    h << "<figure class=\"wide\"><video controls preload=\"auto\" src=\"repertoire/grid.mp4\">"
         "</video><figcaption>Chosen elites on one clock: the farthest walker first, then the "
         "most different footfall patterns; each captioned with its duty factors, swinging "
         "legs coloured, the footfall diagram along the bottom. "
         "<a href=\"repertoire/grid.mp4\">grid.mp4</a></figcaption></figure>\n";
  }
  if (!r.showcase.empty()) {
    h << "<table>\n<tr><th>#</th><th>cell</th><th>duty factors</th><th>distance</th>"
         "<th>found at evaluation</th></tr>\n";
    int n = 0;
    for (const ShowcaseRecord& e : r.showcase) {
      std::string duty;
      for (double d : e.duty_factors) {
        if (!duty.empty()) duty += ' ';
        duty += Fixed(d, 2);
      }
      h << "<tr><td class=\"num\">" << ++n << "</td><td class=\"num\">" << Html(Cell(e.cell))
        << "</td><td>" << Html(duty) << "</td><td class=\"num\">" << Html(Cell(e.distance))
        << "</td><td class=\"num\">" << Html(Cell(e.found_at)) << "</td></tr>\n";
    }
    h << "</table>\n";
  }
  h << "<figure id=\"figure-repertoire-progress\"><img src=\"repertoire/progress.png\" "
       "alt=\"the repertoire growing\"><figcaption><b>How the repertoire grew</b> against "
       "evaluations: cells filled, QD-score (the sum of the elites' distances) and the farthest "
       "standing gait. <a href=\"repertoire/progress.svg\">progress.svg</a></figcaption>"
       "</figure>\n";
}

}  // namespace

int MakeReport(const ReportOptions& options) {
  // Every input is checked before anything is written.
  const std::string run_path = options.run_dir + "/run.json";
  RequireFile(run_path, "hexgait evolve --out " + options.run_dir);
  const RunRecord run = ParseRunRecord(ReadTextFile(run_path), run_path);
  const std::string manifest_path = options.figures_dir + "/" + kFiguresManifest;
  RequireFile(manifest_path,
              "hexgait figures --run " + options.run_dir + " --out " + options.figures_dir);
  const nlohmann::json manifest = ParseJson(ReadTextFile(manifest_path), manifest_path);
  const nlohmann::json& figures = Field(manifest, "figures", manifest_path);
  if (!figures.is_array() || figures.empty()) throw InputError(manifest_path + ": no figures");
  for (const nlohmann::json& f : figures) {
    for (const nlohmann::json& file : Field(f, "files", manifest_path)) {
      RequireFile(options.figures_dir + "/" + file.get<std::string>(),
                  "hexgait figures --run " + options.run_dir + " --out " + options.figures_dir);
    }
  }
  for (const char* movie : kReportMovies) {
    RequireFile(options.movies_dir + "/" + movie,
                "hexgait movie --run " + options.run_dir + " --out " + options.movies_dir);
  }
  for (const char* replay : kReportReplays) {
    RequireFile(options.movies_dir + "/" + replay,
                "hexgait movie --run " + options.run_dir + " --out " + options.movies_dir);
  }
  std::optional<RepertoireRecord> repertoire;
  if (!options.repertoire_dir.empty()) {
    const std::string command = "hexgait repertoire --out " + options.repertoire_dir;
    for (const char* file : kReportRepertoireFiles) {
      RequireFile(options.repertoire_dir + "/" + file, command);
    }
    const std::string json_path = options.repertoire_dir + "/repertoire.json";
    repertoire = ParseRepertoireRecord(ReadTextFile(json_path), json_path);
    if (repertoire->movie) RequireFile(options.repertoire_dir + "/grid.mp4", command);
  }
  std::optional<AdaptSummary> adapt;
  bool adapt_movie = false;
  if (!options.adapt_dir.empty()) {
    const std::string command = "hexgait adapt --out " + options.adapt_dir;
    for (const char* file : kReportAdaptFiles) RequireFile(options.adapt_dir + "/" + file, command);
    const std::string json_path = options.adapt_dir + "/adapt.json";
    adapt = ParseAdaptSummary(ReadTextFile(json_path), json_path);
    std::error_code ec;
    adapt_movie = fs::exists(options.adapt_dir + "/adapt.mp4", ec);
  }
  const OutcomeRecord& unopt = run.unoptimized;
  const OutcomeRecord& best = run.best;
  const double unopt_distance = unopt.distance;
  const double best_distance = best.distance;

  AtomicDir dir(options.out_dir, kReportMarker, "--out");
  fs::create_directory(dir.File("figures"));
  for (const char* movie : kReportMovies) {
    Copy(options.movies_dir + "/" + movie, dir.File(movie));
  }
  for (const char* replay : kReportReplays) {
    Copy(options.movies_dir + "/" + replay, dir.File(replay));
  }
  for (const nlohmann::json& f : figures) {
    for (const nlohmann::json& file : f["files"]) {
      Copy(options.figures_dir + "/" + file.get<std::string>(),
           dir.File("figures/" + file.get<std::string>()));
    }
  }
  Copy(manifest_path, dir.File(std::string("figures/") + kFiguresManifest));
  Copy(run_path, dir.File("run.json"));
  if (repertoire) {
    fs::create_directory(dir.File("repertoire"));
    for (const char* file : kReportRepertoireFiles) {
      Copy(options.repertoire_dir + "/" + file, dir.File(std::string("repertoire/") + file));
    }
    if (repertoire->movie) {
      Copy(options.repertoire_dir + "/grid.mp4", dir.File("repertoire/grid.mp4"));
    }
  }
  if (adapt) {
    fs::create_directory(dir.File("adapt"));
    for (const char* file : kReportAdaptFiles) {
      Copy(options.adapt_dir + "/" + file, dir.File(std::string("adapt/") + file));
    }
    if (adapt_movie) Copy(options.adapt_dir + "/adapt.mp4", dir.File("adapt/adapt.mp4"));
  }

  // A run evolved on a damaged creature says so where the page is named, as its pictures do.
  const std::string damaged = run.damage.empty() ? "" : " (" + Html(DamageNote(run.damage)) + ")";
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>hexgait: evolving legged locomotion, seed " << Html(Cell(run.seed)) << damaged
    << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
    << "<h1>Evolving legged locomotion of a virtual hexapod" << damaged << "</h1>\n"
    << "<p class=\"lead\">A reproduction of Nikovski's experiment by hexgait "
    << Html(Cell(run.hexgait_version))
    << ": a 14-particle, 40-spring creature under an open-loop motor program, its rest lengths "
       "evolved by a genetic algorithm. Everything on this page was made by "
       "<code>hexgait evolve</code>, <code>hexgait movie</code>, <code>hexgait figures</code> "
       "and <code>hexgait report</code>; the files are next to this page.</p>\n";

  // Paper versus ours.
  const double ratio = unopt_distance > 0 ? best_distance / unopt_distance : 0;
  h << "<h2 id=\"result\">The paper's result and ours</h2>\n<table>\n"
    << "<tr><th></th><th>paper</th><th>hexgait (this run)</th></tr>\n"
    << "<tr><th>unoptimized program: fitness</th><td class=\"num\">1064</td><td class=\"num\">"
    << Fixed(unopt_distance, 3) << "</td></tr>\n"
    << "<tr><th>evolved program: fitness</th><td class=\"num\">4070</td><td class=\"num\">"
    << Fixed(best_distance, 3) << "</td></tr>\n"
    << "<tr><th>ratio evolved / unoptimized</th><td class=\"num\">3.83×</td><td class=\"num\">"
    << (unopt_distance > 0 ? Fixed(ratio, 2) + "×" : std::string("–")) << "</td></tr>\n"
    << "<tr><th>unoptimized program</th><td>falls by the end of its 3rd cycle</td><td>"
    << Html(FallText(unopt)) << "</td></tr>\n"
    << "<tr><th>evolved program</th><td>stable for the whole test</td><td>" << Html(FallText(best))
    << "</td></tr>\n"
    << "<tr><th>seed</th><td>–</td><td class=\"num\">" << Html(Cell(run.seed)) << "</td></tr>\n"
    << "<tr><th>population × generations</th><td class=\"num\">4 × 10</td><td class=\"num\">"
    << Html(Cell(run.population)) << " × " << Html(Cell(run.generations)) << "</td></tr>\n"
    << "<tr><th>fitness evaluations</th><td class=\"num\">40</td><td class=\"num\">"
    << Html(Cell(run.evaluations)) << "</td></tr>\n"
    << "</table>\n<p class=\"note\">Fitness is the distance walked along x in "
    << Html(Cell(run.time))
    << " time units: the paper's units are unknown and ours are length units (half a body "
       "length), so compare the ratios, not the values.</p>\n";

  // Movies.
  h << "<h2 id=\"movies\">Gait movies</h2>\n<div class=\"movies\">\n";
  const char* movie_captions[] = {"The unoptimized program (the paper's geometric rest lengths).",
                                  "The evolved program (best.genome).",
                                  "Side by side: unoptimized and evolved."};
  // preload="auto": the files are local, and a loaded video shows its first frame as preview.
  for (int i = 0; i < 3; ++i) {
    h << "<figure" << (i == 2 ? " class=\"wide\"" : "") << "><video controls preload=\"auto\" "
      << "src=\"" << kReportMovies[i] << "\"></video><figcaption>" << movie_captions[i]
      << " <a href=\"" << kReportMovies[i] << "\">" << kReportMovies[i]
      << "</a></figcaption></figure>\n";
  }
  h << "</div>\n";
  // Replays: the same two runs in 3-D, opened paused at the start (#t=0) so that the page does
  // not play two simulations at once.
  h << "<h3 id=\"replays\">Walk around the gait</h3>\n<p class=\"note\">The same two runs in "
       "3-D: drag to orbit, right-drag to pan, scroll to zoom; play, pause and seek below each. "
       "A moment can be linked: <code>evolved.html#t=200&amp;view=side</code>.</p>\n"
       "<div class=\"movies\">\n";
  const char* replay_captions[] = {"The unoptimized program, interactive.",
                                   "The evolved program, interactive."};
  for (int i = 0; i < 2; ++i) {
    h << "<figure><iframe class=\"replay\" title=\"" << replay_captions[i] << "\" src=\""
      << kReportReplays[i] << "#t=0\" loading=\"lazy\"></iframe><figcaption>" << replay_captions[i]
      << " <a href=\"" << kReportReplays[i] << "\">" << kReportReplays[i]
      << "</a> (full window)</figcaption></figure>\n";
  }
  h << "</div>\n";

  // Figures.
  h << "<h2 id=\"figures\">Figures</h2>\n";
  for (const nlohmann::json& f : figures) {
    const std::string name = f["name"].get<std::string>();
    h << "<figure id=\"figure-" << Html(name) << "\"><img src=\"figures/" << Html(name)
      << ".png\" alt=\"" << Html(f["title"].get<std::string>()) << "\"><figcaption><b>"
      << Html(f["title"].get<std::string>()) << ".</b> " << Html(f["caption"].get<std::string>());
    for (const nlohmann::json& file : f["files"]) {
      const std::string fname = file.get<std::string>();
      if (fname.size() > 4 && fname.substr(fname.size() - 4) != ".png") {
        h << " <a href=\"figures/" << Html(fname) << "\">" << Html(fname) << "</a>";
      }
    }
    h << "</figcaption></figure>\n";
  }
  if (manifest.contains("skipped") && !manifest["skipped"].empty()) {
    h << "<p class=\"note\">Not drawn: ";
    bool first = true;
    for (const nlohmann::json& s : manifest["skipped"]) {
      h << (first ? "" : "; ") << Html(s.value("name", "") + ": " + s.value("reason", ""));
      first = false;
    }
    h << ".</p>\n";
  }

  if (repertoire) RepertoireSection(h, *repertoire);
  if (adapt) AdaptSection(h, *adapt, adapt_movie);
  // Parameters and timings.
  h << "<h2 id=\"parameters\">Parameters</h2>\n<table>\n";
  const nlohmann::json parameters = RunRecordJson(run);  // kept alive for items()
  for (const auto& [key, value] : parameters.items()) {
    if (value.is_object() || value.is_array()) continue;
    h << "<tr><th>" << Html(key) << "</th><td>" << Html(Cell(value)) << "</td></tr>\n";
  }
  h << "</table>\n<h2 id=\"timings\">Generations and timings</h2>\n";
  h << "<table>\n<tr><th>generation</th><th>best</th><th>mean</th><th>worst</th>"
       "<th>evaluations</th><th>seconds</th></tr>\n";
  for (const GenerationStats& g : run.history) {
    h << "<tr><td class=\"num\">" << Cell(g.generation) << "</td><td class=\"num\">" << Cell(g.best)
      << "</td><td class=\"num\">" << Cell(g.mean) << "</td><td class=\"num\">" << Cell(g.worst)
      << "</td><td class=\"num\">" << Cell(g.evaluations) << "</td><td class=\"num\">"
      << Cell(g.seconds) << "</td></tr>\n";
  }
  h << "</table>\n<table>\n"
    << "<tr><th>evolution wall time</th><td class=\"num\">" << Html(Cell(run.wall_seconds))
    << " s on " << Html(Cell(run.threads)) << " thread(s)</td></tr>\n"
    << "<tr><th>per evaluation (one core)</th><td class=\"num\">"
    << Html(Cell(run.seconds_per_evaluation)) << " s</td></tr>\n"
    << "<tr><th>figures (both programs simulated, plotted)</th><td class=\"num\">"
    << Html(Cell(Get(manifest, "wall_seconds"))) << " s</td></tr>\n"
    << "</table>\n<p class=\"note\">Run files: <a href=\"run.json\">run.json</a>, "
       "<a href=\"figures/figures.json\">figures/figures.json</a>.</p>\n"
    << "</body>\n</html>\n";
  WriteFileAtomically(dir.File("index.html"), h.str());
  dir.Commit();
  return static_cast<int>(figures.size());
}

}  // namespace hexgait
