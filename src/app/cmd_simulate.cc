// hexgait simulate: run one creature and report distance, fall and run time.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "run/simulate_run.h"
#include "util/error.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

// `--csv -`: the trace on standard output, for a pipe. Written once, after the run, so a failed
// or stopped run prints no partial table.
void WriteStandardOutput(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    throw InputError("--csv -: cannot write to standard output");
  }
}

void Run(const SimulateFile& opt) {
  const double duration = opt.time;
  const double dt = opt.scene.dt;
  ProgressBar bar("simulating");
  const SimulatedFile out =
      SimulateToFile(opt, [&](std::string_view stage, long long done, long long total) {
        char detail[64];
        std::snprintf(detail, sizeof detail, "t = %.0f of %g", static_cast<double>(done) * dt,
                      duration);
        bar.Show(stage, done, total, detail);
      });
  bar.Clear();
  const RunResult& result = out.simulated.result;
  const double seconds = out.simulated.seconds;
  const Scene& scene = out.scene;
  if (opt.csv_path == "-") {
    WriteStandardOutput(out.csv_text);
    // Standard output holds the table alone; the report goes to stderr.
    PrintRunReport(result, out.run, out.label, scene.model, scene.program.cycle_period, stderr);
    std::fprintf(stderr, "run time   %.3f s\n", seconds);
    return;
  }
  if (opt.json) {
    nlohmann::json j =
        RunReportJson(result, out.run, out.label, scene.model, scene.program.cycle_period);
    j["wall_seconds"] = seconds;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    PrintRunReport(result, out.run, out.label, scene.model, scene.program.cycle_period);
    std::printf("run time   %.3f s\n", seconds);
    if (!opt.csv_path.empty()) std::printf("trace      %s\n", opt.csv_path.c_str());
  }
}

}  // namespace

void RegisterSimulate(CLI::App& app) {
  auto opt = std::make_shared<SimulateFile>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run one creature and report the distance it walked and whether it fell");
  AddGenomeOptions(cmd, opt->genome);
  AddSceneOptions(cmd, opt->scene);
  cmd->add_option("--time", opt->time, "Simulated time (time units; 1000 is the paper's)")
      ->capture_default_str();
  cmd->add_option("--csv", opt->csv_path,
                  "Write a trace: time, body centre, lowest body particle, tilt, feet on ground "
                  "('-': to standard output, with the report on stderr)");
  cmd->add_option("--csv-interval", opt->csv_interval, "Time between trace rows")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object instead of text (for scripts)");
  cmd->add_flag("--early-stop", opt->early_stop,
                "End the run once the creature has fallen and lain still for a gait cycle");
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
