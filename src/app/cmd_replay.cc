// hexgait replay: one run as a self-contained interactive 3-D page for a web browser.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "run/replay_request.h"
#include "util/progress_bar.h"

namespace hexgait {

namespace {

void Run(const ReplayFile& opt) {
  ProgressBar bar("simulating");
  const ReplayWritten written = WriteReplay(
      opt, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }, bar.Hook());
  bar.Clear();
  std::printf("wrote %s (%.0f KB, %lld frames of %s over %g time units)\n", opt.out.c_str(),
              written.bytes / 1024.0, written.settings.frames, written.label.c_str(),
              written.settings.run.duration);
}

}  // namespace

void RegisterReplay(CLI::App& app) {
  auto opt = std::make_shared<ReplayFile>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Write one run as a self-contained HTML page to watch in a browser: orbit, pan and zoom "
      "around the creature, play, pause and seek (no network needed)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--run", opt->run_dir, "Replay the best.genome of this 'hexgait evolve' folder");
  ReplayRequest& replay = opt->replay;
  cmd->add_option("--time", replay.time, "Simulated time units to replay")->capture_default_str();
  cmd->add_flag("--no-overlay", replay.no_overlay,
                "Open with the springs and particles hidden (a checkbox on the page)");
  cmd->add_flag("--no-shadow", replay.no_shadow, "Open with the shadow hidden");
  AddViewOptions(cmd, replay.view, true);
  AddSceneOptions(cmd, opt->scene);
  cmd->add_option("--out", opt->out, "HTML file to write")->capture_default_str();
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
