// hexgait replay: one run as a self-contained interactive 3-D page for a web browser.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "run/folder_scene.h"
#include "run/io_paths.h"
#include "run/replay_request.h"
#include "run/run_state.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/progress_bar.h"

namespace hexgait {

namespace {

struct ReplayOptions {
  SceneOptions scene;
  GenomeChoice genome;
  std::string run_dir;
  ReplayRequest replay;
  std::string out = "out/replay.html";
};

void Run(ReplayOptions opt) {
  if (!opt.run_dir.empty()) {
    if (!opt.genome.path.empty() || opt.genome.unoptimized) {
      throw InputError(
          "--run replays that run's best.genome: give --run, --genome or "
          "--unoptimized, not two");
    }
    IoPaths().Input("--run", opt.run_dir).Check();
    opt.genome.path = FinishedRunGenome(opt.run_dir, "--run");
    opt.scene = SceneOfFolders(opt.scene, {{"--run", opt.run_dir}});  // the run's own scene
  }
  SceneInputs(opt.scene, &opt.genome).Output("--out", opt.out).Check();
  CheckExtension(opt.out, ".html", "--out");
  CheckOutputPath(opt.out, "--out");
  const Scene scene = LoadScene(opt.scene);
  const ReplaySettings settings = MakeReplaySettings(opt.replay, opt.scene, scene);
  if (!settings.decimation.empty()) std::fprintf(stderr, "%s\n", settings.decimation.c_str());
  std::string label;
  const Genome genome = LoadGenomeChoice(opt.genome, scene, &label);
  ProgressBar bar("simulating");
  const std::string page =
      ReplayHtml(scene, genome, settings, label, [&](long long done, long long total) {
        bar.Update(static_cast<double>(done) / static_cast<double>(total));
      });
  bar.Clear();
  WriteFileAtomically(opt.out, page);
  std::printf("wrote %s (%.0f KB, %lld frames of %s over %g time units)\n", opt.out.c_str(),
              page.size() / 1024.0, settings.frames, label.c_str(), settings.run.duration);
}

}  // namespace

void RegisterReplay(CLI::App& app) {
  auto opt = std::make_shared<ReplayOptions>();
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
