// The subcommands of `hexgait`. Each Register* adds its CLI11 subcommand and the callback
// that runs it.
#pragma once

#include <CLI/CLI.hpp>

namespace hexgait {

void RegisterSimulate(CLI::App& app);
void RegisterEvolve(CLI::App& app);
void RegisterSweep(CLI::App& app);
void RegisterEndurance(CLI::App& app);
void RegisterRepertoire(CLI::App& app);
void RegisterInspect(CLI::App& app);
void RegisterStill(CLI::App& app);
void RegisterFilmstrip(CLI::App& app);
void RegisterRender(CLI::App& app);
void RegisterMovie(CLI::App& app);
void RegisterBench(CLI::App& app);
void RegisterFigures(CLI::App& app);
void RegisterReport(CLI::App& app);
void RegisterReplay(CLI::App& app);
void RegisterAdapt(CLI::App& app);
void RegisterCompare(CLI::App& app);
// Subcommands of `hexgait bench` (cmd_bench.cc holds the parent).
void AddBenchAccuracy(CLI::App& bench);   // cmd_bench_accuracy.cc
void AddBenchStability(CLI::App& bench);  // cmd_bench_stability.cc

}  // namespace hexgait
