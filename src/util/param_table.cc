#include "util/param_table.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "util/error.h"

namespace hexgait {
std::string ParamText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

ParamValues ParamValues::Defaults(const ParamTable& table, const ParamValues& given) {
  ParamValues values = given;
  for (const ParamSpec& spec : table) {
    const bool has = given.Has(spec.name);
    values.Set(spec.name, has ? given.Get(spec.name) : spec.value, spec.integer);
  }
  return values;
}

double ParamValues::Get(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("no parameter '" + name + "'");
  return it->second.number;
}

int ParamValues::Integer(const std::string& name) const {
  return static_cast<int>(Get(name));
}

void ParamValues::Set(const std::string& name, double number, bool integer) {
  values_[name] = Value{number, integer};
}

nlohmann::json ParamsToJson(const ParamValues& values) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : values.all()) {
    if (value.integer) {
      j[name] = static_cast<long long>(value.number);
    } else {
      j[name] = value.number;
    }
  }
  return j;
}

std::string FlagOf(const std::string& name) {
  std::string flag = "--" + name;
  for (char& c : flag) c = c == '_' ? '-' : c;
  return flag;
}

const ParamSpec* FindParam(const ParamTable& table, const std::string& name) {
  for (const ParamSpec& spec : table) {
    if (name == spec.name) return &spec;
  }
  return nullptr;
}

void CheckParams(const ParamTable& table, const ParamValues& values, const std::string& owner) {
  for (const auto& [name, value] : values.all()) {
    if (!FindParam(table, name)) throw InputError(FlagOf(name) + " is not a parameter of " + owner);
  }
  for (const ParamSpec& spec : table) {
    const std::string flag = FlagOf(spec.name);
    if (!values.Has(spec.name)) throw InputError(owner + " needs " + flag);
    const double v = values.Get(spec.name);
    if (!(v >= spec.min && v <= spec.max)) {
      throw InputError(flag + " must be in [" + ParamText(spec.min) + ", " + ParamText(spec.max) +
                       "] for " + owner);
    }
    if (spec.integer && v != std::floor(v)) throw InputError(flag + " must be a whole number");
  }
}

std::string DescribeParams(const ParamValues& values) {
  std::string text;
  for (const auto& [name, value] : values.all()) {
    text += (text.empty() ? "" : ", ") + name + " " + ParamText(value.number);
  }
  return text;
}

}  // namespace hexgait
