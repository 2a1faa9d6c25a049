#include "app/bench_common.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "motor/assets.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/temp_registry.h"

namespace hexgait {

void AddCommonOptions(CLI::App* cmd, BenchCommon& c) {
  cmd->add_option("--out", c.out_dir, "Folder for the CSV files")->capture_default_str();
  cmd->add_flag("--quick", c.quick, "A small version for tests: few steps, short runs");
  cmd->add_option("--creature", c.creature,
                  "Creature: a built-in name (" + BuiltInCreatureList() +
                      ") or a creature file; it runs its own built-in motor program");
  cmd->add_option("--integrators", c.integrators,
                  "Comma-separated integrators to run (default: all of euler, symplectic-euler, "
                  "verlet, rk4, implicit-euler)");
}

std::vector<IntegratorKind> ParseIntegratorList(const std::string& text) {
  if (text.empty()) return AllIntegrators();
  std::vector<IntegratorKind> kinds;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) kinds.push_back(ParseIntegrator(name));
  if (kinds.empty()) throw InputError("--integrators: no integrator named");
  return kinds;
}

BenchOutDir::BenchOutDir(const std::string& out_dir, const char* first_file) : folder_(out_dir) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(out_dir, ec);
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw InputError("--out '" + out_dir + "': cannot create folder" +
                     (ec ? ": " + ec.message() : ""));
  }
  if (!existed) temp_handle_ = RegisterTemp(out_dir);
  path_ = out_dir + "/";
  CheckOutputPath(path_ + first_file, "--out");
}

BenchOutDir::~BenchOutDir() {
  if (temp_handle_ == 0) return;
  std::error_code ec;
  std::filesystem::remove(folder_, ec);  // only if empty: results are written atomically
  UnregisterTemp(temp_handle_);
}

void BenchOutDir::Keep() {
  if (temp_handle_ != 0) UnregisterTemp(temp_handle_);
  temp_handle_ = 0;
}

void PrintProgressLine(const std::string& line) {
  std::fprintf(stderr, "bench: %s\n", line.c_str());
}

}  // namespace hexgait
