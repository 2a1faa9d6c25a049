// hexgait compare: does an image or a movie look like the approved one? Exit 0 when it does, 1
// when it does not (with a one-line summary), 2 when they cannot be compared, like cmp and diff.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "run/compare_request.h"
#include "util/error.h"

namespace hexgait {

namespace {

void Run(const CompareRequest& request) {
  CompareResult result;
  try {
    result = CompareFiles(request);
  } catch (const InputError& e) {
    std::fprintf(stderr, "hexgait: error: %s\n", e.what());
    throw ExitWith{2};
  }
  std::printf("%s\n", result.summary.c_str());
  if (!result.diff_path.empty()) std::printf("wrote %s\n", result.diff_path.c_str());
  if (!result.match) throw ExitWith{1};
}

}  // namespace

void RegisterCompare(CLI::App& app) {
  auto request = std::make_shared<CompareRequest>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare an image or movie with an approved one (golden-image check): PNG stills as "
      "images, movies frame by frame. Exit 0 when they match within the tolerance, 1 when they "
      "differ, 2 when they cannot be compared");
  cmd->add_option("EXPECTED", request->expected, "The approved file (.png, or a .mp4 movie)")
      ->required();
  cmd->add_option("ACTUAL", request->actual, "The file to check, of the same kind")->required();
  cmd->add_option("--tolerance", request->tolerance.max_different_fraction,
                  "Fraction of an image's (or each frame's) pixels that may differ")
      ->capture_default_str();
  cmd->add_option("--pixel-threshold", request->tolerance.pixel_threshold,
                  "Levels (of 255) a colour channel may move before its pixel differs")
      ->capture_default_str();
  cmd->add_option("--diff", request->diff,
                  "Write a PNG showing where they differ (differing pixels in red; a movie's "
                  "worst frame)");
  cmd->callback([request] { Run(*request); });
}

}  // namespace hexgait
