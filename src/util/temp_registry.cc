#include "util/temp_registry.h"

#include <filesystem>
#include <map>
#include <mutex>

namespace hexgait {
namespace {

std::mutex g_mutex;
std::map<int, std::string> g_temps;
int g_next = 0;

}  // namespace

int CreateRegisteredTemp(const std::function<std::string()>& create) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_temps[++g_next] = create();
  return g_next;
}

int RegisterTemp(const std::string& path) {
  return CreateRegisteredTemp([&] { return path; });
}

void CommitTemp(const std::function<void()>& commit) {
  std::lock_guard<std::mutex> lock(g_mutex);
  commit();
}

void UnregisterTemp(int handle) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_temps.erase(handle);
}

void RemoveAllTempsForExit() {
  // The mutex is taken and never released: the process is about to exit, and a thread that
  // tries to create a new temporary waits instead of creating it.
  g_mutex.lock();
  for (const auto& [handle, path] : g_temps) {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  g_temps.clear();
}

}  // namespace hexgait
