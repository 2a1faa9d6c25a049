// hexgait bench: measurements anyone can re-run; each kind is a subcommand.
#include "app/bench_movie.h"
#include "app/commands.h"

namespace hexgait {

void RegisterBench(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks: run time, accuracy, memory");
  bench->require_subcommand(1);
  AddBenchMovie(*bench);
}

}  // namespace hexgait
