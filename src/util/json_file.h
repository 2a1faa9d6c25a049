// Reading JSON data files with errors that name the file and the field.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hexgait {

// Data files are small (the hexapod is 13 KB); a larger one is a mistake, refused before
// it is read or parsed.
constexpr size_t kMaxDataFileBytes = 16 << 20;
// Deeper JSON nesting than any data file needs; refused before parsing.
constexpr int kMaxJsonDepth = 32;

// Reads a whole text file; throws InputError naming the path for a missing, unreadable,
// empty, oversized (above `max_bytes`) or non-text file, a directory or a FIFO. A leading UTF-8
// byte-order mark is dropped.
std::string ReadTextFile(const std::string& path, size_t max_bytes = kMaxDataFileBytes);

// Throws InputError unless `text` is at most `max_bytes` of UTF-8 without control characters
// other than tab, CR and LF; the message names the byte offset and line.
void CheckText(const std::string& text, const std::string& source,
               size_t max_bytes = kMaxDataFileBytes);

// Checks the text (CheckText), its nesting depth, then parses; `source` names it in error
// messages (a path or "embedded ...").
nlohmann::json ParseJson(const std::string& text, const std::string& source,
                         size_t max_bytes = kMaxDataFileBytes);

// "16 MB": a size limit as error messages state it.
std::string MegabytesText(size_t bytes);

// Integers in records hexgait reads back (run.json, repertoire.json, endurance.json, scale
// measurements). nlohmann's get<int>() and value(key, 0) cast any number unchecked: a fraction
// is truncated and a float beyond the type (1e24) is undefined behaviour. These accept only a
// JSON integer within [lo, hi] and otherwise throw nlohmann::json::out_of_range, which every
// record reader already turns into one line naming the file.
long long IntegerIn(const nlohmann::json& value, long long lo, long long hi);
int IntIn(const nlohmann::json& value, int lo, int hi);
uint64_t UnsignedInteger(const nlohmann::json& value);
// A seed as records write it: a non-negative JSON integer, or its decimal digits as a string
// (repertoire.json and adapt.json: 64 bits survive readers whose numbers are doubles). Anything
// else, "-1", "12abc", a fraction or a value past 64 bits, is refused like IntegerIn's.
uint64_t SeedValue(const nlohmann::json& value);
// The member `key` if present (IntegerIn), else `fallback`: fields older files lack.
long long IntegerOr(const nlohmann::json& object, const char* key, long long fallback, long long lo,
                    long long hi);
int IntOr(const nlohmann::json& object, const char* key, int fallback, int lo, int hi);

// Field access that names the file and the JSON path of the offending value.
class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string source, std::string where)
      : value_(value), source_(std::move(source)), where_(std::move(where)) {}

  const nlohmann::json& value() const { return value_; }
  const std::string& where() const { return where_; }
  [[noreturn]] void Fail(const std::string& what) const;

  // Rejects keys not in `allowed`, so a typo in a data file is an error, not a silent default.
  void RequireOnlyKeys(const std::vector<std::string>& allowed) const;
  JsonReader Child(const std::string& key) const;  // required object or array member
  bool Has(const std::string& key) const;
  JsonReader At(size_t index) const;  // requires an array with that element
  size_t ArraySize() const;           // requires an array

  double Number(const std::string& key) const;  // finite number
  double PositiveNumber(const std::string& key) const;
  double NonNegativeNumber(const std::string& key) const;
  int Integer(const std::string& key) const;
  std::string String(const std::string& key) const;
  bool Bool(const std::string& key) const;

  double AsNumber() const;
  int AsInteger() const;
  std::string AsString() const;

 private:
  const nlohmann::json& value_;
  std::string source_;
  std::string where_;
};

}  // namespace hexgait
