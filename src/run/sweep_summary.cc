#include "run/sweep_summary.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "record/run_record.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/median.h"

namespace hexgait {
namespace {

// The same limit as any data file hexgait reads.
constexpr size_t kMaxRunJsonBytes = 16u << 20;

}  // namespace

std::vector<std::string> RunFoldersOf(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(fs::path(folder) / ".hexgait-sweep", ec)) return {folder};
  std::vector<std::pair<unsigned long long, std::string>> seeds;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("seed-", 0) != 0 || !entry.is_directory(ec)) continue;
    const std::string digits = name.substr(5);
    if (digits.empty() || digits.size() > 19 ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
      continue;
    }
    seeds.emplace_back(std::stoull(digits), entry.path().string());
  }
  std::sort(seeds.begin(), seeds.end());
  std::vector<std::string> folders;
  for (const auto& [seed, path] : seeds) folders.push_back(path);
  if (folders.empty()) throw InputError("'" + folder + "': a sweep folder without seed-K/ runs");
  return folders;
}

SeedSummary ReadSeedSummary(const std::string& folder) {
  const std::string path = folder + "/run.json";
  const RunRecord run = ParseRunRecord(ReadTextFile(path, kMaxRunJsonBytes), path);
  SeedSummary s;
  s.seed = run.seed;
  s.population = run.population;
  s.generations = run.generations;
  s.evaluations = run.evaluations;
  s.unoptimized_distance = run.unoptimized.distance;
  s.unoptimized_fell = run.unoptimized.fell;
  s.unoptimized_fall_cycle = run.unoptimized.fell ? run.unoptimized.fall_cycle.value_or(-1) : -1;
  s.best_distance = run.best_fitness;
  s.best_fell = run.best.fell;
  s.best_fall_cycle = run.best.fell ? run.best.fall_cycle.value_or(-1) : -1;
  s.ratio = run.ratio().value_or(0.0);
  s.unoptimized_diverged = run.unoptimized.diverged;
  s.best_diverged = run.best.diverged;
  for (const GenerationStats& g : run.history) s.diverged_evaluations += g.diverged;
  return s;
}

std::string SummaryCsv(const std::vector<SeedSummary>& seeds) {
  std::ostringstream out;
  out << "seed,evaluations,unoptimized_distance,unoptimized_fell,unoptimized_fall_cycle,"
         "best_distance,best_fell,best_fall_cycle,ratio,unoptimized_diverged,best_diverged,"
         "diverged_evaluations\n";
  char line[360];
  for (const SeedSummary& s : seeds) {
    std::snprintf(line, sizeof line, "%llu,%d,%.17g,%d,%d,%.17g,%d,%d,%.17g,%d,%d,%d\n",
                  static_cast<unsigned long long>(s.seed), s.evaluations, s.unoptimized_distance,
                  s.unoptimized_fell ? 1 : 0, s.unoptimized_fall_cycle, s.best_distance,
                  s.best_fell ? 1 : 0, s.best_fall_cycle, s.ratio, s.unoptimized_diverged ? 1 : 0,
                  s.best_diverged ? 1 : 0, s.diverged_evaluations);
    out << line;
  }
  return out.str();
}

std::string SeedTableMarkdown(const std::vector<SeedSummary>& seeds,
                              const std::string& seeds_text) {
  std::string text =
      "| budget | seeds | evaluations per run | unoptimized distance (fall cycle) | "
      "best/unoptimized: median | worst | best | seeds whose best does not fall | "
      "evaluations that diverged |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  if (seeds.empty()) return text;
  std::vector<double> ratios;
  int standing = 0;
  long long diverged = 0, evaluations = 0;
  for (const SeedSummary& s : seeds) {
    ratios.push_back(s.ratio);
    standing += s.best_fell || s.best_diverged ? 0 : 1;
    diverged += s.diverged_evaluations;
    evaluations += s.evaluations;
  }
  const SeedSummary& first = seeds.front();
  const std::string fall = first.unoptimized_diverged ? std::string("diverged")
                           : first.unoptimized_fell
                               ? "cycle " + std::to_string(first.unoptimized_fall_cycle)
                               : std::string("no fall");
  char row[512];
  std::snprintf(row, sizeof row,
                "| population %d, %d generations | %s | %d | %.2f (%s) | %.2fx | %.2fx | %.2fx | "
                "%d of %zu | %lld of %lld |\n",
                first.population, first.generations, seeds_text.c_str(), first.evaluations,
                first.unoptimized_distance, fall.c_str(), Median(ratios, 0),
                *std::min_element(ratios.begin(), ratios.end()),
                *std::max_element(ratios.begin(), ratios.end()), standing, seeds.size(), diverged,
                evaluations);
  return text + row;
}

}  // namespace hexgait
