// Replays every fuzz seed (tests/fuzz/corpus/<name>/) and every past fuzz finding
// (tests/fuzz/regressions/<name>/) through the parser its fuzz target drives: each must parse
// or throw InputError, and nothing else. Under ASan/UBSan (scripts/test.sh) this also checks
// them for memory errors and undefined behaviour without needing clang or libFuzzer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/fuzz_inputs.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

int ReplayFolder(const fuzz::FuzzParser& parser, const fs::path& folder) {
  if (!fs::is_directory(folder)) return 0;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    ++files;
    const std::string bytes = ReadBytes(entry.path());
    try {
      parser.parse(bytes);
    } catch (const InputError&) {
      // A clean, one-line refusal is the expected outcome for bad input.
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << parser.name
                    << " threw a non-InputError: " << e.what();
    }
  }
  return files;
}

TEST(FuzzRegression, CorpusAndFindingsParseOrGiveInputError) {
  const fs::path root = fs::path(HEXGAIT_SOURCE_DIR) / "tests" / "fuzz";
  for (const fuzz::FuzzParser& parser : fuzz::FuzzParsers()) {
    SCOPED_TRACE(parser.name);
    // Every target has a seed corpus, so a renamed folder cannot silently skip it.
    EXPECT_GT(ReplayFolder(parser, root / "corpus" / parser.name), 0);
    ReplayFolder(parser, root / "regressions" / parser.name);
  }
}

TEST(FuzzRegression, RealAssetsParse) {
  const fs::path corpus = fs::path(HEXGAIT_SOURCE_DIR) / "tests" / "fuzz" / "corpus";
  EXPECT_NO_THROW(fuzz::ParseCreatureInput(ReadBytes(corpus / "creature" / "hexapod.json")));
  EXPECT_NO_THROW(fuzz::ParseCreatureInput(ReadBytes(corpus / "creature" / "wedge.json")));
  EXPECT_NO_THROW(
      fuzz::ParseMotorProgramInput(ReadBytes(corpus / "motor_program" / "metachronal.json")));
  EXPECT_NO_THROW(fuzz::ParseGenomeInput(ReadBytes(corpus / "genome" / "evolved_seed1.genome")));
  // Records as hexgait repertoire and hexgait endurance wrote them.
  EXPECT_NO_THROW(fuzz::ParseRepertoireRecordInput(
      ReadBytes(corpus / "repertoire_record" / "repertoire.json")));
  EXPECT_NO_THROW(
      fuzz::ParseEnduranceRecordInput(ReadBytes(corpus / "endurance_record" / "endurance.json")));
}

// The text checks every parser runs first (util/json_file.h: CheckText, ParseJson).
TEST(TextCheck, RefusesBinaryInvalidUtf8AndDeepNesting) {
  EXPECT_NO_THROW(CheckText("caf\xC3\xA9 \xF0\x9F\x98\x80\t\r\n", "t"));
  EXPECT_THROW(CheckText(std::string("a\0b", 3), "t"), InputError);
  EXPECT_THROW(CheckText("\xC0\xAF", "t"), InputError);          // overlong '/'
  EXPECT_THROW(CheckText("\xED\xA0\x80", "t"), InputError);      // surrogate
  EXPECT_THROW(CheckText("\xF4\x90\x80\x80", "t"), InputError);  // above U+10FFFF
  EXPECT_THROW(CheckText("\xE2\x82", "t"), InputError);          // truncated
  EXPECT_NO_THROW(
      ParseJson(std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']'), "t"));
  EXPECT_THROW(
      ParseJson(std::string(kMaxJsonDepth + 1, '[') + std::string(kMaxJsonDepth + 1, ']'), "t"),
      InputError);
  // Brackets inside strings do not count as nesting.
  EXPECT_NO_THROW(ParseJson("[\"" + std::string(100, '[') + "\\\"\"]", "t"));
  // A huge unsigned integer must not wrap to a small (valid-looking) index.
  const nlohmann::json huge = ParseJson("[18446744073709551615]", "t");
  EXPECT_THROW(JsonReader(huge, "t", "").At(0).AsInteger(), InputError);
}

}  // namespace
}  // namespace hexgait
