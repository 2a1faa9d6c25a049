// hexgait report: the static HTML page of the whole experiment (src/report/report_page.h).
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "run/report_request.h"

namespace hexgait {

void RegisterReport(CLI::App& app) {
  auto opt = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report", "Write a self-contained HTML page of the experiment: movies, figures, results");
  cmd->add_option("--run", opt->run_dir, "'hexgait evolve' folder (run.json)")
      ->capture_default_str();
  cmd->add_option("--movies", opt->movies_dir,
                  "Folder with unoptimized.mp4, evolved.mp4 and comparison.mp4 ('hexgait movie')")
      ->capture_default_str();
  cmd->add_option("--figures", opt->figures_dir, "'hexgait figures' folder")->capture_default_str();
  cmd->add_option("--repertoire", opt->repertoire_dir,
                  "'hexgait repertoire' folder: adds its map, movie grid and comparison");
  cmd->add_option("--adapt", opt->adapt_dir,
                  "'hexgait adapt' folder: adds a section on adapting to damage");
  cmd->add_option("--out", opt->out_dir, "Folder to write (replaced whole)")->capture_default_str();
  cmd->callback([opt] {
    const int figures = WriteReport(*opt);
    std::printf("wrote %s/index.html (%d figures, 3 movies, 2 replays%s%s)\n", opt->out_dir.c_str(),
                figures, opt->repertoire_dir.empty() ? "" : ", the repertoire",
                opt->adapt_dir.empty() ? "" : ", adapting to damage");
  });
}

}  // namespace hexgait
