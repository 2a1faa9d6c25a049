// The parsers under fuzzing, one function each, shared by the libFuzzer targets
// (tests/fuzz/*_fuzz.cc) and by the regression test that replays the corpus and every past
// finding through the same code (tests/unit/fuzz_regression_test.cc).
//
// Contract checked by both: any byte string either parses or throws InputError. Any other
// exception, a crash, a sanitizer report, a leak or a hang is a bug.
//
// Adding a parser: one function here, one row in FuzzParsers(), a `<name>_fuzz.cc` that
// invokes HEXGAIT_FUZZ_TARGET, and the name in tests/fuzz/CMakeLists.txt.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "util/error.h"

namespace hexgait::fuzz {

void ParseCreatureInput(const std::string& text);
void ParseMotorProgramInput(const std::string& text);  // against the built-in hexapod
void ParseGenomeInput(const std::string& text);        // either layout, built-in creature
void ParseCheckpointInput(const std::string& text);    // evolve checkpoint, built-in creature
void ParseJsonInput(const std::string& text);          // generic JSON data file access
void ParseArchiveInput(const std::string& text);       // repertoire archive.json, built-in creature
void ParseRunRecordInput(const std::string& text);     // run.json, what sweep and figures read
// Any optimizer's checkpoint (the GA's or CMA-ES's) as evolve --resume reads it.
void ParseSearchCheckpointInput(const std::string& text);
void ParseAdaptRecordInput(const std::string& text);       // adapt.json, what report --adapt reads
void ParseRepertoireRecordInput(const std::string& text);  // repertoire.json, what report reads
void ParseEnduranceRecordInput(const std::string& text);   // endurance.json

struct FuzzParser {
  std::string name;  // the target's name: tests/fuzz/<name>_fuzz.cc, corpus/<name>/
  void (*parse)(const std::string& text);
};
const std::vector<FuzzParser>& FuzzParsers();

}  // namespace hexgait::fuzz

// Defines libFuzzer's entry point for one parser; InputError is the expected outcome for bad
// input, everything else escapes and is reported by libFuzzer.
#define HEXGAIT_FUZZ_TARGET(parse_function)                                   \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {   \
    try {                                                                     \
      parse_function(std::string(reinterpret_cast<const char*>(data), size)); \
    } catch (const hexgait::InputError&) {                                    \
    }                                                                         \
    return 0;                                                                 \
  }
