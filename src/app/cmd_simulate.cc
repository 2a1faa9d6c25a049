// hexgait simulate: run one creature and report distance, fall and run time.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli_common.h"
#include "app/commands.h"
#include "run/simulate_run.h"
#include "sim/trace.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

struct SimulateOptions {
  SceneOptions scene;
  GenomeChoice genome;
  double time = kPaperDuration;
  std::string csv_path;
  double csv_interval = 0.1;
  bool json = false;
  bool early_stop = false;
};

std::string TraceCsv(const CreatureModel& model, const std::vector<TraceSample>& samples) {
  std::ostringstream out;
  out << "time,centre_x,centre_y,centre_z,lowest_body_z,tilt_degrees";
  for (const Leg& leg : model.legs) out << ",foot_" << leg.name;
  out << '\n';
  char line[256];
  for (const TraceSample& s : samples) {
    std::snprintf(line, sizeof line, "%.4f,%.6f,%.6f,%.6f,%.6f,%.3f", s.time, s.centre.x(),
                  s.centre.y(), s.centre.z(), s.lowest_body, s.tilt_degrees);
    out << line;
    for (size_t leg = 0; leg < model.legs.size(); ++leg)
      out << ',' << ((s.feet_on_ground >> leg) & 1u);
    out << '\n';
  }
  return out.str();
}

// `--csv -`: the trace on standard output, for a pipe. Written once, after the run, so a failed
// or stopped run prints no partial table.
void WriteStandardOutput(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    throw InputError("--csv -: cannot write to standard output");
  }
}

void Run(const SimulateOptions& opt) {
  RunOptions run = MakeRunOptions(opt.scene, opt.time);
  run.early_stop = opt.early_stop;
  const bool csv_to_stdout = opt.csv_path == "-";
  if (csv_to_stdout && opt.json) {
    throw InputError("--csv - and --json both write to standard output; choose one");
  }
  if (!opt.csv_path.empty()) {
    if (!csv_to_stdout) {
      SceneInputs(opt.scene, &opt.genome).Output("--csv", opt.csv_path).Check();
      CheckOutputPath(opt.csv_path, "--csv");
    }
    if (!(opt.csv_interval >= opt.scene.dt && opt.csv_interval <= opt.time)) {
      throw InputError("--csv-interval must be between --dt and --time");  // before any work
    }
  }
  const Scene scene = LoadScene(opt.scene);
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  SimulateRequest request;
  if (!opt.csv_path.empty()) request.interval = opt.csv_interval;
  ProgressBar bar("simulating");
  const SimulatedRun simulated = SimulateGenome(
      scene, genome, run, request, "--csv-interval", [&](long long done, long long total) {
        char detail[64];
        std::snprintf(detail, sizeof detail, "t = %.0f of %g", static_cast<double>(done) * run.dt,
                      run.duration);
        bar.Update(static_cast<double>(done) / static_cast<double>(total), detail);
      });
  bar.Clear();
  const RunResult& result = simulated.result;
  const double seconds = simulated.seconds;
  const bool trace = !opt.csv_path.empty();
  if (trace && csv_to_stdout) {
    WriteStandardOutput(TraceCsv(scene.model, simulated.samples));
    // Standard output holds the table alone; the report goes to stderr.
    PrintRunReport(result, run, label, scene.model, scene.program.cycle_period, stderr);
    std::fprintf(stderr, "run time   %.3f s\n", seconds);
    return;
  }
  if (trace) WriteFileAtomically(opt.csv_path, TraceCsv(scene.model, simulated.samples));

  if (opt.json) {
    nlohmann::json j = RunReportJson(result, run, label, scene.model, scene.program.cycle_period);
    j["wall_seconds"] = seconds;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    PrintRunReport(result, run, label, scene.model, scene.program.cycle_period);
    std::printf("run time   %.3f s\n", seconds);
    if (!opt.csv_path.empty()) std::printf("trace      %s\n", opt.csv_path.c_str());
  }
}

}  // namespace

void RegisterSimulate(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
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
