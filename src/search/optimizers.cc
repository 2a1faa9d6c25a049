// The registries of `evolve --algorithm` and `repertoire --algorithm`: one line per optimizer.
#include <nlohmann/json.hpp>

#include "search/archive_optimizer.h"
#include "search/generational.h"
#include "util/error.h"

// One line per optimizer, each ending in a backslash; the blank line ends the list.
// clang-format off
#define HEXGAIT_OPTIMIZERS(X) \
  X(kGaOptimizer)             \
  X(kCmaEsOptimizer)          \

#define HEXGAIT_ARCHIVE_OPTIMIZERS(X) \
  X(kMapElitesOptimizer)              \
  X(kCmaMaeOptimizer)                 \
  X(kIsoLineOptimizer)

// clang-format on

namespace hexgait {

#define HEXGAIT_DECLARE_OPTIMIZER(kind) extern const OptimizerKind kind;
HEXGAIT_OPTIMIZERS(HEXGAIT_DECLARE_OPTIMIZER)
#undef HEXGAIT_DECLARE_OPTIMIZER

#define HEXGAIT_DECLARE_ARCHIVE_OPTIMIZER(kind) extern const ArchiveOptimizerKind kind;
HEXGAIT_ARCHIVE_OPTIMIZERS(HEXGAIT_DECLARE_ARCHIVE_OPTIMIZER)
#undef HEXGAIT_DECLARE_ARCHIVE_OPTIMIZER

namespace {

// The kind called `name` among `kinds`; throws InputError listing their names.
template <class Kind>
const Kind& FindKind(const std::vector<const Kind*>& kinds, const std::string& name) {
  std::string names;
  for (const Kind* kind : kinds) {
    if (name == kind->name) return *kind;
    names += (names.empty() ? "" : ", ") + std::string(kind->name);
  }
  throw InputError("--algorithm '" + name + "' is not one of " + names);
}

}  // namespace

const std::vector<const ArchiveOptimizerKind*>& ArchiveOptimizerKinds() {
#define HEXGAIT_LIST_OPTIMIZER(kind) &kind,
  static const std::vector<const ArchiveOptimizerKind*> kinds = {
      HEXGAIT_ARCHIVE_OPTIMIZERS(HEXGAIT_LIST_OPTIMIZER)};
#undef HEXGAIT_LIST_OPTIMIZER
  return kinds;
}

const ArchiveOptimizerKind& FindArchiveOptimizerKind(const std::string& name) {
  return FindKind(ArchiveOptimizerKinds(), name);
}

const ArchiveOptimizerKind* ArchiveOptimizerKindOrNull(const std::string& name) {
  for (const ArchiveOptimizerKind* kind : ArchiveOptimizerKinds()) {
    if (name == kind->name) return kind;
  }
  return nullptr;
}

const OptimizerKind& FindOptimizerKindOfAny(const std::string& name) {
  std::string names;
  for (const OptimizerKind* kind : OptimizerKinds()) {
    if (name == kind->name) return *kind;
    names += std::string(kind->name) + ", ";
  }
  for (const ArchiveOptimizerKind* kind : ArchiveOptimizerKinds()) {
    names += std::string(kind->name) + (kind == ArchiveOptimizerKinds().back() ? "" : ", ");
  }
  throw InputError("algorithm '" + name + "' is not one of " + names);
}

const std::vector<const OptimizerKind*>& OptimizerKinds() {
#define HEXGAIT_LIST_OPTIMIZER(kind) &kind,
  static const std::vector<const OptimizerKind*> kinds = {
      HEXGAIT_OPTIMIZERS(HEXGAIT_LIST_OPTIMIZER)};
#undef HEXGAIT_LIST_OPTIMIZER
  return kinds;
}

const OptimizerKind& FindOptimizerKind(const std::string& name) {
  return FindKind(OptimizerKinds(), name);
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
