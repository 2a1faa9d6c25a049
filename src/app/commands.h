// The subcommands of `hexgait`. Each Register* adds its CLI11 subcommand and the callback
// that runs it.
#pragma once

#include <CLI/CLI.hpp>

namespace hexgait {

void RegisterSimulate(CLI::App& app);
void RegisterEvolve(CLI::App& app);
void RegisterInspect(CLI::App& app);
void RegisterStill(CLI::App& app);
void RegisterRender(CLI::App& app);
void RegisterBench(CLI::App& app);

}  // namespace hexgait
