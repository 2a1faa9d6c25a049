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
// The output folder of a benchmark, made and checked (a file can be written there) before any
// work starts. A folder it had to create is removed again unless Keep() is called once the
// results are written: when the command is stopped by a signal (util/temp_registry) or fails,
// no empty folder is left behind. A folder that existed is never removed.
class BenchOutDir {
 public:
  BenchOutDir(const std::string& out_dir, const char* first_file);
  ~BenchOutDir();
  BenchOutDir(const BenchOutDir&) = delete;
  BenchOutDir& operator=(const BenchOutDir&) = delete;

  const std::string& path() const { return path_; }  // with a trailing slash
  void Keep();

 private:
  std::string folder_, path_;
  int temp_handle_ = 0;  // registered while a folder this made may still be removed
};
// One progress line on stderr.
void PrintProgressLine(const std::string& line);

}  // namespace hexgait
