#include "search/stored_results.h"

#include <algorithm>
#include <cstdio>

#include "ga/checkpoint_json.h"
#include "util/error.h"

namespace hexgait {
namespace {

// Which of `count` to replay: all, or `limit` spread evenly with the first and the last.
std::vector<size_t> Sample(size_t count, size_t limit) {
  std::vector<size_t> picks;
  if (count <= limit) {
    for (size_t i = 0; i < count; ++i) picks.push_back(i);
    return picks;
  }
  limit = std::max<size_t>(limit, 2);
  for (size_t k = 0; k < limit; ++k) picks.push_back(k * (count - 1) / (limit - 1));
  return picks;
}

// "distance 4.186 stored, 3.902 replayed": the first field that differs.
std::string Difference(const RunResult& stored, const RunResult& replayed) {
  const nlohmann::json a = ResultJson(stored);
  const nlohmann::json b = ResultJson(replayed);
  for (auto it = a.begin(); it != a.end(); ++it) {
    if (b.contains(it.key()) && b[it.key()] != it.value()) {
      return it.key() + " " + it.value().dump() + " stored, " + b[it.key()].dump() + " replayed";
    }
  }
  return "the results differ";
}

}  // namespace

std::string ReplayCheck::Text(const std::string& what) const {
  char text[200];
  if (replayed == stored) {
    std::snprintf(text, sizeof text, "replayed all %zu stored %s: every result matches", stored,
                  what.c_str());
  } else {
    std::snprintf(text, sizeof text,
                  "replayed %zu of %zu stored %s (an even sample): every result matches", replayed,
                  stored, what.c_str());
  }
  return text;
}

std::vector<StoredResult> StoredElites(const Archive& archive, const CreatureModel& model,
                                       const MotorProgram& program) {
  std::vector<StoredResult> stored;
  for (int cell : archive.filled()) {
    const Elite& elite = *archive.at(cell);
    stored.push_back({"the elite in cell " + std::to_string(cell),
                      PerturbedRestLengths(model, program, elite.genome), elite.result});
  }
  return stored;
}

ReplayCheck ReplayStoredResults(const std::vector<StoredResult>& stored, Evaluator& evaluator,
                                const std::string& source, size_t max_replays, int threads,
                                const Progress& between) {
  const std::vector<size_t> picks = Sample(stored.size(), max_replays);
  std::vector<RestLengthTable> tables;
  tables.reserve(picks.size());
  for (size_t i : picks) tables.push_back(stored[i].table);
  const std::vector<RunResult> replayed =
      between ? EvaluateInSlices(evaluator, tables, threads, 0.25, between)
              : evaluator.Evaluate(tables);
  for (size_t k = 0; k < picks.size(); ++k) {
    const StoredResult& s = stored[picks[k]];
    if (ResultJson(replayed[k]) != ResultJson(s.result)) {
      throw InputError(source + ": " + s.name + " does not replay to its stored result (" +
                       Difference(s.result, replayed[k]) +
                       "): the file was edited, or written by a build that simulates "
                       "differently; start a new run");
    }
  }
  return {picks.size(), stored.size()};
}

}  // namespace hexgait
