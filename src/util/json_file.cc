#include "util/json_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "util/error.h"

namespace hexgait {

namespace {

[[noreturn]] void FailInteger(const nlohmann::json& value, const std::string& what) {
  throw nlohmann::json::out_of_range::create(406, what, &value);
}

}  // namespace

long long IntegerIn(const nlohmann::json& value, long long lo, long long hi) {
  if (!value.is_number_integer()) {
    std::string what = "expected an integer, got ";
    what += value.is_number_float() ? value.dump() : std::string(value.type_name());
    FailInteger(value, what);
  }
  // Compared as the JSON type it is: an unsigned value above LLONG_MAX must not wrap.
  const bool above = value.is_number_unsigned()
                         ? value.get<unsigned long long>() > static_cast<unsigned long long>(hi)
                         : value.get<long long>() > hi;
  if (above || (!value.is_number_unsigned() && value.get<long long>() < lo)) {
    FailInteger(value, "integer " + value.dump() + " outside " + std::to_string(lo) + ".." +
                           std::to_string(hi));
  }
  return value.is_number_unsigned() ? static_cast<long long>(value.get<unsigned long long>())
                                    : value.get<long long>();
}

int IntIn(const nlohmann::json& value, int lo, int hi) {
  return static_cast<int>(IntegerIn(value, lo, hi));
}

uint64_t UnsignedInteger(const nlohmann::json& value) {
  if (!value.is_number_integer() || (!value.is_number_unsigned() && value.get<long long>() < 0)) {
    FailInteger(value, "expected a non-negative integer, got " + value.dump());
  }
  return value.get<uint64_t>();
}

uint64_t SeedValue(const nlohmann::json& value) {
  if (!value.is_string()) return UnsignedInteger(value);
  const std::string& digits = value.get_ref<const std::string&>();
  uint64_t seed = 0;
  const char* end = digits.data() + digits.size();
  const auto [stop, error] = std::from_chars(digits.data(), end, seed);
  if (digits.empty() || digits[0] < '0' || digits[0] > '9' || stop != end || error != std::errc()) {
    FailInteger(value, "expected a seed (decimal digits, at most 2^64 - 1), got " + value.dump());
  }
  return seed;
}

long long IntegerOr(const nlohmann::json& object, const char* key, long long fallback, long long lo,
                    long long hi) {
  const auto it = object.find(key);
  return it == object.end() ? fallback : IntegerIn(*it, lo, hi);
}

int IntOr(const nlohmann::json& object, const char* key, int fallback, int lo, int hi) {
  return static_cast<int>(IntegerOr(object, key, fallback, lo, hi));
}

std::string MegabytesText(size_t bytes) {
  return std::to_string(bytes >> 20) + " MB";
}

std::string ReadTextFile(const std::string& path, size_t max_bytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw FileError("'" + path + "': is a directory, expected a file");
  }
  if (!std::filesystem::exists(path, ec)) throw FileError("'" + path + "': no such file");
  // Opening a FIFO would wait for a writer forever, and reading a terminal (/dev/tty, or
  // /dev/stdin at a prompt) for the user: data files are regular files. Checked before the file
  // is opened, through links.
  if (std::filesystem::is_fifo(path, ec) || std::filesystem::is_socket(path, ec)) {
    throw FileError("'" + path + "': is a FIFO or socket, expected a regular file");
  }
  if (std::filesystem::is_character_file(path, ec) || std::filesystem::is_block_file(path, ec)) {
    throw FileError("'" + path + "': is a device, expected a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("'" + path + "': cannot be opened for reading");
  // Read in chunks up to one byte more than allowed, so /dev/zero or a huge file cannot
  // exhaust memory and a large limit is not allocated up front.
  std::string result;
  std::string chunk(1 << 20, '\0');
  while (result.size() <= max_bytes && in) {
    const size_t want = std::min(chunk.size(), max_bytes + 1 - result.size());
    in.read(chunk.data(), static_cast<std::streamsize>(want));
    result.append(chunk.data(), static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) throw FileError("'" + path + "': read error");
  if (result.size() > max_bytes) {
    throw InputError("'" + path + "': file is larger than " + MegabytesText(max_bytes) +
                     ", not a hexgait data file");
  }
  CheckText(result, "'" + path + "'", max_bytes);
  // A UTF-8 byte-order mark (editors on Windows write one) is not part of the text: without
  // this, a genome file's first line would read as an unknown word.
  if (result.compare(0, 3, "\xEF\xBB\xBF") == 0) result.erase(0, 3);
  if (result.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError("'" + path + "': file is empty");
  }
  return result;
}

namespace {

size_t LineOf(const std::string& text, size_t offset) {
  size_t line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// Length of the UTF-8 sequence starting at text[i], or 0 if it is not valid UTF-8
// (overlong forms, surrogates and code points above U+10FFFF are invalid).
size_t Utf8SequenceLength(const std::string& text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    length = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    length = 3;
    if (c == 0xE0) low = 0xA0;
    if (c == 0xED) high = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    length = 4;
    if (c == 0xF0) low = 0x90;
    if (c == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// Deepest nesting of [ and { outside strings, stopping early once past `limit`.
int NestingDepth(const std::string& text, int limit, size_t* where) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) {
        *where = i;
        break;
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

void CheckText(const std::string& text, const std::string& source, size_t max_bytes) {
  if (text.size() > max_bytes) {
    throw InputError(source + ": larger than " + MegabytesText(max_bytes) +
                     ", not a hexgait data file");
  }
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", c);
        throw InputError(source + ": not a text file (control byte " + hex + " at line " +
                         std::to_string(LineOf(text, i)) + ")");
      }
      ++i;
      continue;
    }
    const size_t length = Utf8SequenceLength(text, i);
    if (length == 0) {
      throw InputError(source + ": not a text file (invalid UTF-8 at line " +
                       std::to_string(LineOf(text, i)) + ", byte " + std::to_string(i) + ")");
    }
    i += length;
  }
}

nlohmann::json ParseJson(const std::string& text, const std::string& source, size_t max_bytes) {
  CheckText(text, source, max_bytes);
  size_t deep_at = 0;
  if (NestingDepth(text, kMaxJsonDepth, &deep_at) > kMaxJsonDepth) {
    throw InputError(source + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                     " levels at line " + std::to_string(LineOf(text, deep_at)));
  }
  // A key given twice in one object is refused: nlohmann keeps the last silently, so an edit
  // that adds a field instead of changing it would be ignored.
  std::vector<std::set<std::string>> keys;  // per open object
  std::string duplicate;
  const nlohmann::json::parser_callback_t check_keys = [&](int, nlohmann::json::parse_event_t event,
                                                           nlohmann::json& parsed) {
    if (event == nlohmann::json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == nlohmann::json::parse_event_t::object_end) {
      keys.pop_back();
    } else if (event == nlohmann::json::parse_event_t::key && duplicate.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!keys.back().insert(key).second) duplicate = key;
    }
    return true;
  };
  try {
    nlohmann::json result = nlohmann::json::parse(text, check_keys);
    if (!duplicate.empty()) {
      throw InputError(source + ": key '" + duplicate + "' appears twice in one object");
    }
    return result;
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the offset; turn it into a line number a person can find.
    const size_t line = LineOf(text, e.byte);
    std::string what = e.what();
    const size_t colon = what.rfind(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw InputError(source + ": malformed JSON at line " + std::to_string(line) + ": " + what);
  } catch (const nlohmann::json::exception& e) {
    // For example a number too large for a double (out_of_range 406).
    std::string what = e.what();
    const size_t bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    throw InputError(source + ": malformed JSON: " + what);
  }
}

void JsonReader::Fail(const std::string& what) const {
  throw InputError(source_ + ": " + (where_.empty() ? std::string("top level") : where_) + ": " +
                   what);
}

void JsonReader::RequireOnlyKeys(const std::vector<std::string>& allowed) const {
  if (!value_.is_object()) Fail("expected an object");
  for (const auto& item : value_.items()) {
    bool known = false;
    for (const auto& key : allowed) known = known || key == item.key();
    if (!known) {
      std::string list;
      for (const auto& key : allowed) list += (list.empty() ? "" : ", ") + key;
      Fail("unknown field '" + item.key() + "' (expected: " + list + ")");
    }
  }
}

bool JsonReader::Has(const std::string& key) const {
  return value_.is_object() && value_.contains(key);
}

JsonReader JsonReader::Child(const std::string& key) const {
  if (!value_.is_object()) Fail("expected an object");
  if (!value_.contains(key)) Fail("missing field '" + key + "'");
  return JsonReader(value_.at(key), source_, where_.empty() ? key : where_ + "." + key);
}

JsonReader JsonReader::At(size_t index) const {
  if (index >= ArraySize()) Fail("expected at least " + std::to_string(index + 1) + " elements");
  return JsonReader(value_.at(index), source_, where_ + "[" + std::to_string(index) + "]");
}

size_t JsonReader::ArraySize() const {
  if (!value_.is_array()) Fail("expected an array");
  return value_.size();
}

double JsonReader::AsNumber() const {
  if (!value_.is_number()) Fail("expected a number, got " + std::string(value_.type_name()));
  const double v = value_.get<double>();
  if (!std::isfinite(v)) Fail("number is not finite");
  return v;
}

int JsonReader::AsInteger() const {
  if (!value_.is_number_integer()) {
    Fail("expected an integer, got " + std::string(value_.type_name()));
  }
  // Checked as the JSON type it is: a huge unsigned value must not wrap to a small one.
  if (value_.is_number_unsigned() && value_.get<unsigned long long>() > 1000000000ULL) {
    Fail("integer out of range");
  }
  const auto v = value_.get<long long>();
  if (v < -1000000000LL || v > 1000000000LL) Fail("integer out of range");
  return static_cast<int>(v);
}

std::string JsonReader::AsString() const {
  if (!value_.is_string()) Fail("expected a string, got " + std::string(value_.type_name()));
  std::string text = value_.get<std::string>();
  // An escaped control character ("\u001b") passes the file's text check but would reach the
  // terminal in messages and captions.
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) Fail("control character in a string");
  }
  return text;
}

double JsonReader::Number(const std::string& key) const {
  return Child(key).AsNumber();
}

double JsonReader::PositiveNumber(const std::string& key) const {
  const JsonReader child = Child(key);
  const double v = child.AsNumber();
  if (!(v > 0)) child.Fail("must be positive, got " + std::to_string(v));
  return v;
}

double JsonReader::NonNegativeNumber(const std::string& key) const {
  const JsonReader child = Child(key);
  const double v = child.AsNumber();
  if (v < 0) child.Fail("must not be negative, got " + std::to_string(v));
  return v;
}

int JsonReader::Integer(const std::string& key) const {
  return Child(key).AsInteger();
}
std::string JsonReader::String(const std::string& key) const {
  return Child(key).AsString();
}

bool JsonReader::Bool(const std::string& key) const {
  const JsonReader child = Child(key);
  if (!child.value().is_boolean()) child.Fail("expected true or false");
  return child.value().get<bool>();
}

}  // namespace hexgait
