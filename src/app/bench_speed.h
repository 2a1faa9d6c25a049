// `hexgait bench speed`: ns per creature-step and evaluations per second for the naive loop,
// the scalar path, the batched kernel on one core and on all cores, with the flop rate against
// the core's measured peak.
#pragma once

#include <CLI/CLI.hpp>

namespace hexgait {

void AddBenchSpeed(CLI::App& bench);
// `hexgait bench early-stop` (cmd_bench_early_stop.cc): what --early-stop saves and changes.
void AddBenchEarlyStop(CLI::App& bench);
// `hexgait bench scale` (cmd_bench_scale.cc): evaluations per second across MPI ranks, and the
// cluster model of docs/scaling.md.
void AddBenchScale(CLI::App& bench);

}  // namespace hexgait
