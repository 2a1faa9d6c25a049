#include "app/bench_common.h"

#include <cstdio>

#include "motor/assets.h"

namespace hexgait {

void AddCommonOptions(CLI::App* cmd, BenchFolderRequest& c) {
  cmd->add_option("--out", c.out_dir, "Folder for the CSV files")->capture_default_str();
  cmd->add_flag("--quick", c.quick, "A small version for tests: few steps, short runs");
  cmd->add_option("--creature", c.creature,
                  "Creature: a built-in name (" + BuiltInCreatureList() +
                      ") or a creature file; it runs its own built-in motor program");
  cmd->add_option("--integrators", c.integrators,
                  "Comma-separated integrators to run (default: all of euler, symplectic-euler, "
                  "verlet, rk4, implicit-euler)");
}

void PrintProgressLine(const std::string& line) {
  std::fprintf(stderr, "bench: %s\n", line.c_str());
}

}  // namespace hexgait
