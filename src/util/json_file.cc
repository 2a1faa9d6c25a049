#include "util/json_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace hexgait {

std::string ReadTextFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError("'" + path + "': is a directory, expected a file");
  }
  if (!std::filesystem::exists(path, ec)) throw InputError("'" + path + "': no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("'" + path + "': cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("'" + path + "': read error");
  std::string result = text.str();
  if (result.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError("'" + path + "': file is empty");
  }
  return result;
}

nlohmann::json ParseJson(const std::string& text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the offset; turn it into a line number a person can find.
    size_t line = 1;
    for (size_t i = 0; i < e.byte && i < text.size(); ++i) line += text[i] == '\n';
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
  const auto v = value_.get<long long>();
  if (v < -1000000000LL || v > 1000000000LL) Fail("integer out of range");
  return static_cast<int>(v);
}

std::string JsonReader::AsString() const {
  if (!value_.is_string()) Fail("expected a string, got " + std::string(value_.type_name()));
  return value_.get<std::string>();
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
