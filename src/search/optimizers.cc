// The registry of `evolve --algorithm`: one line per optimizer.
#include <nlohmann/json.hpp>

#include "search/generational.h"
#include "util/error.h"

#define HEXGAIT_OPTIMIZERS(X) \
  X(kGaOptimizer)             \
  X(kCmaEsOptimizer)

namespace hexgait {

#define HEXGAIT_DECLARE_OPTIMIZER(kind) extern const OptimizerKind kind;
HEXGAIT_OPTIMIZERS(HEXGAIT_DECLARE_OPTIMIZER)
#undef HEXGAIT_DECLARE_OPTIMIZER

const std::vector<const OptimizerKind*>& OptimizerKinds() {
#define HEXGAIT_LIST_OPTIMIZER(kind) &kind,
  static const std::vector<const OptimizerKind*> kinds = {
      HEXGAIT_OPTIMIZERS(HEXGAIT_LIST_OPTIMIZER)};
#undef HEXGAIT_LIST_OPTIMIZER
  return kinds;
}

const OptimizerKind& FindOptimizerKind(const std::string& name) {
  std::string names;
  for (const OptimizerKind* kind : OptimizerKinds()) {
    if (name == kind->name) return *kind;
    names += (names.empty() ? "" : ", ") + std::string(kind->name);
  }
  throw InputError("--algorithm '" + name + "' is not one of " + names);
}

const OptimizerKind& CheckpointKind(const std::string& text) {
  const nlohmann::json root = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  const auto format = root.is_object() ? root.find("format") : root.end();
  if (root.is_object() && format != root.end() && format->is_string()) {
    for (const OptimizerKind* kind : OptimizerKinds()) {
      if (*format == kind->checkpoint_format) return *kind;
    }
  }
  // The first kind's reader gives the precise message (not JSON, unknown format, ...).
  return *OptimizerKinds().front();
}

}  // namespace hexgait
