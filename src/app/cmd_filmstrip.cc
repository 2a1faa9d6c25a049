// hexgait filmstrip: frames across one gait cycle side by side in one PNG (movie/filmstrip.h).
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/view_options.h"
#include "run/filmstrip_request.h"
#include "util/progress_bar.h"

namespace hexgait {
namespace {

void Run(const FilmstripFile& opt) {
  ProgressBar bar("simulating");
  const FilmstripWritten written = WriteFilmstrip(opt, bar.Hook());
  bar.Clear();
  const FilmstripResult& result = written.result;
  const std::string& label = written.label;
  const std::string damaged = written.damage.empty() ? "" : ", damaged: " + written.damage;
  std::printf("wrote %s (%dx%d, %s, gait cycle %d in %d frames%s%s)\n", opt.out.c_str(),
              result.image.width, result.image.height, label.c_str(), opt.filmstrip.cycle,
              opt.filmstrip.frames, result.run.fell ? ", fallen" : "", damaged.c_str());
  ReportExpected(written.expected);
}

}  // namespace

void RegisterFilmstrip(CLI::App& app) {
  auto opt = std::make_shared<FilmstripFile>();
  FilmstripRequest& f = opt->filmstrip;
  CLI::App* cmd = app.add_subcommand(
      "filmstrip",
      "Render frames across one gait cycle side by side in one PNG (a locomotion paper's figure)");
  AddGenomeOptions(cmd, opt->genome);
  cmd->add_option("--cycle", f.cycle, "Gait cycle shown (1 is the first)")->capture_default_str();
  cmd->add_option("--frames", f.frames, "Frames across the cycle (2 to 24)")->capture_default_str();
  cmd->add_option("--size", f.size, "Size of each frame, WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--msaa", f.msaa, "Anti-aliasing samples per pixel: 0 (off), 2, 4 or 8")
      ->capture_default_str();
  cmd->add_flag("--no-shadow", f.no_shadow, "Do not draw the shadow on the ground");
  cmd->add_option("--out", opt->out, "PNG file to write")->capture_default_str();
  AddExpectOption(cmd, opt->expect);
  AddViewOptions(cmd, f.view, true, kFilmstripView);
  AddGlOption(cmd);
  AddSceneOptions(cmd, opt->scene);
  cmd->callback([opt] { Run(*opt); });
}

}  // namespace hexgait
