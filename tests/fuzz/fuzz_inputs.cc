#include "fuzz_inputs.h"

#include <memory>

#include "ga/checkpoint.h"
#include "ga/genome.h"
#include "ga/genome_io.h"
#include "ga/map_elites_checkpoint.h"
#include "model/creature_io.h"
#include "motor/assets.h"
#include "motor/motor_program_io.h"
#include "record/adapt_record.h"
#include "record/endurance_record.h"
#include "record/repertoire_record.h"
#include "record/run_record.h"
#include "search/archive_optimizer.h"
#include "search/generational.h"
#include "util/json_file.h"

namespace hexgait::fuzz {
namespace {

const char kSource[] = "fuzz input";

// The built-in creature and program, parsed once: the fuzzers vary only the input under test.
struct Defaults {
  CreatureModel model = LoadCreatureOrDefault("");
  MotorProgram program = LoadMotorProgramOrDefault("", model);
  std::shared_ptr<const GenomeLayout> full = MakeGenomeLayout(model, program, false);
  std::shared_ptr<const GenomeLayout> symmetric = MakeGenomeLayout(model, program, true);
};

const Defaults& BuiltIn() {
  static const Defaults defaults;
  return defaults;
}

// Reads every value through every accessor, as a data-file loader might; each may refuse.
void Walk(const JsonReader& r, int depth) {
  auto attempt = [](auto&& read) {
    try {
      read();
    } catch (const InputError&) {
    }
  };
  attempt([&] { r.AsNumber(); });
  attempt([&] { r.AsInteger(); });
  attempt([&] { r.AsString(); });
  attempt([&] { r.RequireOnlyKeys({"name"}); });
  attempt([&] { r.PositiveNumber("mass"); });
  attempt([&] { r.Bool("motor"); });
  if (depth > 64) return;
  if (r.value().is_object()) {
    for (const auto& item : r.value().items()) Walk(r.Child(item.key()), depth + 1);
  } else if (r.value().is_array()) {
    for (size_t i = 0; i < r.ArraySize(); ++i) Walk(r.At(i), depth + 1);
    attempt([&] { r.At(r.ArraySize()); });  // one past the end must be refused, not UB
  }
}

}  // namespace

void ParseCreatureInput(const std::string& text) {
  ParseCreature(text, kSource);
}

void ParseMotorProgramInput(const std::string& text) {
  ParseMotorProgram(text, kSource, BuiltIn().model);
}

void ParseGenomeInput(const std::string& text) {
  const bool symmetric = GenomeFileIsSymmetric(text, kSource);
  ParseGenome(text, kSource, symmetric ? BuiltIn().symmetric : BuiltIn().full);
}

void ParseCheckpointInput(const std::string& text) {
  ParseCheckpoint(text, kSource, BuiltIn().model, BuiltIn().program);
}

void ParseJsonInput(const std::string& text) {
  const nlohmann::json doc = ParseJson(text, kSource);
  Walk(JsonReader(doc, kSource, ""), 0);
}

void ParseArchiveInput(const std::string& text) {
  // Then the optimizer that would continue it: its settings and its own saved state (CMA-MAE's
  // emitters and thresholds) are read and checked there.
  MakeArchiveOptimizer(SearchScene{BuiltIn().model, BuiltIn().program, ""},
                       ParseArchive(text, kSource, BuiltIn().model, BuiltIn().program));
}

void ParseRunRecordInput(const std::string& text) {
  ParseRunRecord(text, kSource);
}

void ParseAdaptRecordInput(const std::string& text) {
  ParseAdaptSummary(text, kSource);
}

void ParseRepertoireRecordInput(const std::string& text) {
  ParseRepertoireRecord(text, kSource);
}

void ParseEnduranceRecordInput(const std::string& text) {
  ParseEnduranceRecord(text, kSource);
}

void ParseSearchCheckpointInput(const std::string& text) {
  bool unchecked = false;
  CheckpointKind(text).resume(SearchScene{BuiltIn().model, BuiltIn().program, ""}, text, kSource,
                              &unchecked);
}

const std::vector<FuzzParser>& FuzzParsers() {
  static const std::vector<FuzzParser> parsers = {
      {"creature", ParseCreatureInput},
      {"motor_program", ParseMotorProgramInput},
      {"genome", ParseGenomeInput},
      {"json", ParseJsonInput},
      {"checkpoint", ParseCheckpointInput},
      {"archive", ParseArchiveInput},
      {"run_record", ParseRunRecordInput},
      {"search_checkpoint", ParseSearchCheckpointInput},
      {"adapt_record", ParseAdaptRecordInput},
      {"repertoire_record", ParseRepertoireRecordInput},
      {"endurance_record", ParseEnduranceRecordInput},
  };
  return parsers;
}

}  // namespace hexgait::fuzz
