// hexgait bench: the parent of the benchmark subcommands, one file each.
#include "app/bench_movie.h"
#include "app/bench_speed.h"
#include "app/commands.h"

namespace hexgait {

void RegisterBench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Benchmarks: run time against error, numerical stability, simulation speed, early stop, "
      "movie speed, scaling across MPI ranks");
  bench->require_subcommand(1);
  AddBenchAccuracy(*bench);
  AddBenchStability(*bench);
  AddBenchSpeed(*bench);
  AddBenchEarlyStop(*bench);
  AddBenchScale(*bench);
  AddBenchMovie(*bench);
}

}  // namespace hexgait
