// Shared by the `hexgait bench` subcommands: the integrator benchmarks' common flags and the
// progress lines.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "run/bench_request.h"

namespace hexgait {

void AddCommonOptions(CLI::App* cmd, BenchFolderRequest& c);
// One progress line on stderr.
void PrintProgressLine(const std::string& line);

}  // namespace hexgait
