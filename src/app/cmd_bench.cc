// hexgait bench: measurements of the simulator itself (bench speed, ...).
#include "app/bench_speed.h"
#include "app/commands.h"

namespace hexgait {

void RegisterBench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Measure the simulator (speed, early-stop)");
  bench->require_subcommand(1);
  AddBenchSpeed(*bench);
  AddBenchEarlyStop(*bench);
}

}  // namespace hexgait
