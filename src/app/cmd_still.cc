// hexgait still: one rendered frame as a PNG; by default the paper's Figure 1.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "run/still_request.h"
#include "util/progress_bar.h"

namespace hexgait {

namespace {

void Run(const StillFile& opt) {
  ProgressBar bar("simulating");
  const StillWritten still = WriteStill(opt, bar.Hook());
  bar.Clear();
  const std::string damaged = still.damage.empty() ? "" : ", damaged: " + still.damage;
  std::printf("wrote %s (%dx%d, %s at t = %g%s)\n", opt.out.c_str(), still.image.width,
              still.image.height, still.label.c_str(), opt.still.time, damaged.c_str());
  ReportExpected(still.expected);
}

}  // namespace

void RegisterStill(CLI::App& app) {
  auto opt = std::make_shared<StillFile>();
  CLI::App* cmd = app.add_subcommand(
      "still", "Render one frame as a PNG (default: the paper's Figure 1, the creature at rest)");
  AddGenomeOptions(cmd, opt->genome);
  StillRequest& still = opt->still;
  cmd->add_option("--time", still.time, "Simulated time of the frame (0: the rest pose)")
      ->capture_default_str();
  cmd->add_option("--size", still.size, "Image size, WIDTHxHEIGHT")->capture_default_str();
  cmd->add_flag("--no-overlay", still.no_overlay,
                "Hide the springs and particles drawn over the polygons");
  cmd->add_flag("--no-shadow", still.no_shadow, "Do not draw the shadow on the ground");
  cmd->add_option("--msaa", still.msaa, "Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8")
      ->capture_default_str();
  AddViewOptions(cmd, still.view, true);
  AddGlOption(cmd);
  AddSceneOptions(cmd, opt->scene);
  cmd->add_option("--out", opt->out, "PNG file to write")->capture_default_str();
  AddExpectOption(cmd, opt->expect);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
