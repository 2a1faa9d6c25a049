// hexgait bench: the parent of the benchmark subcommands, one file each.
#include "app/commands.h"

namespace hexgait {

void RegisterBench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Benchmarks: run time against error, and numerical stability stress tests");
  bench->require_subcommand(1);
  AddBenchAccuracy(*bench);
  AddBenchStability(*bench);
  // `hexgait bench speed` is added here by AddBenchSpeed(*bench) (the batched speed path).
}

}  // namespace hexgait
