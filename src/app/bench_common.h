// Shared by the `hexgait bench` subcommands: common flags, the integrator list, the output
// folder and progress lines.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "sim/integrator.h"

namespace hexgait {

struct BenchCommon {
  std::string out_dir = "out/bench";
  bool quick = false;
  std::string integrators;  // comma-separated; empty: all
  std::string creature;     // a built-in name or a creature file; empty: the default
};

void AddCommonOptions(CLI::App* cmd, BenchCommon& c);
// "a,b" -> integrators; empty -> all. Throws InputError on an unknown name.
std::vector<IntegratorKind> ParseIntegratorList(const std::string& text);
// Creates the output folder and checks a file can be written there, before any work starts;
// returns the folder with a trailing slash.
std::string PrepareOutDir(const std::string& out_dir, const char* first_file);
// The CPU's model name from /proc/cpuinfo, for benchmark headers.
std::string CpuModel();
// One progress line on stderr.
void Progress(const std::string& line);

}  // namespace hexgait
