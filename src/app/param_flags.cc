#include "app/param_flags.h"

#include <cstdio>

namespace hexgait {
ParamFlags::ParamFlags(CLI::App* command, const std::vector<ParamOwner>& owners)
    : command_(command) {
  // Each parameter's help: "Help (cma-mae, default 0.5; ...)", in the order first met.
  std::vector<std::string> order;
  std::map<std::string, std::string> help;
  for (const auto& [owner, table] : owners) {
    for (const ParamSpec& spec : *table) {
      if (!values_.count(spec.name)) {
        order.push_back(spec.name);
        values_[spec.name] = Flag{spec.value, spec.integer};
        help[spec.name] = std::string(spec.help) + " (";
      } else {
        help[spec.name] += "; ";
      }
      help[spec.name] += owner + ": default " + ParamText(spec.value) + ", in [" +
                         ParamText(spec.min) + ", " + ParamText(spec.max) + "]";
    }
  }
  for (const std::string& name : order) {
    command->add_option(FlagOf(name), values_[name].value, help[name] + ")")
        ->type_name(values_[name].integer ? "INT" : "FLOAT");
  }
}

ParamValues ParamFlags::Given() const {
  ParamValues given;
  for (const auto& [name, flag] : values_) {
    if (command_->count(FlagOf(name)) > 0) given.Set(name, flag.value, flag.integer);
  }
  return given;
}

std::vector<std::string> ParamFlags::flags() const {
  std::vector<std::string> out;
  for (const auto& [name, flag] : values_) out.push_back(FlagOf(name));
  return out;
}

}  // namespace hexgait
