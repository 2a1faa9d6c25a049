// An algorithm's own parameters, declared once in a table: name, kind, default, range and help.
// Everything else reads the table: the command's flags (`--learning-rate`), Python's keywords
// (`learning_rate=`), the record and the checkpoint (key "learning_rate"), `--resume`'s
// refusals and the checks, so adding a parameter is one row.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hexgait {

struct ParamSpec {
  const char* name;  // snake_case: the record's key and Python's keyword
  bool integer;      // whole numbers only
  double value;      // the default
  double min, max;   // allowed range, both ends included
  const char* help;  // for --help and Python's docstring
};

using ParamTable = std::vector<ParamSpec>;

// Values by name (sorted), each remembering whether it is a whole number.
class ParamValues {
 public:
  struct Value {
    double number = 0;
    bool integer = false;
    bool operator==(const Value&) const = default;
  };

  // The table's defaults, with `given` values in their place (kept as given: CheckParams
  // refuses one the table lacks).
  static ParamValues Defaults(const ParamTable& table, const ParamValues& given = {});

  bool Has(const std::string& name) const { return values_.count(name) > 0; }
  // The value called `name`; throws std::logic_error when there is none (a programming error:
  // the table and its reader disagree).
  double Get(const std::string& name) const;
  int Integer(const std::string& name) const;
  void Set(const std::string& name, double number, bool integer);
  const std::map<std::string, Value>& all() const { return values_; }
  bool operator==(const ParamValues&) const = default;

 private:
  std::map<std::string, Value> values_;
};

// {"learning_rate": 0.01, "emitters": 25}: whole numbers as JSON integers.
nlohmann::json ParamsToJson(const ParamValues& values);

// "--learning-rate" for "learning_rate".
std::string FlagOf(const std::string& name);
// The table's row called `name`, or null.
const ParamSpec* FindParam(const ParamTable& table, const std::string& name);
// Throws InputError naming the flag when a value is missing, not in the table ("--sigma is not
// a parameter of map-elites"), out of range or not a whole number where one is needed.
void CheckParams(const ParamTable& table, const ParamValues& values, const std::string& owner);
// A value as --help, the checks' messages and the headers print it ("%g": 0.01, 25, 1e+06).
std::string ParamText(double value);
// "learning_rate 0.01, sigma 0.5": every value, for a run's header.
std::string DescribeParams(const ParamValues& values);

}  // namespace hexgait
