// hexgait inspect: the creature's structure and the numbers docs/model.md quotes: rigidity,
// natural frequencies, and the explicit Euler stability margin of every spring and contact.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "run/inspect_request.h"

namespace hexgait {

void RegisterInspect(CLI::App& app) {
  auto opt = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand(
      "inspect", "Print the creature's structure, natural frequencies and Euler step margins");
  AddSceneOptions(cmd, *opt, false);
  cmd->callback([opt] { std::fputs(InspectReport(*opt).c_str(), stdout); });
}

}  // namespace hexgait
