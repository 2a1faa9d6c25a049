// The flags of the optimizers' parameter tables (util/param_table.h): one flag per parameter,
// added from the tables, so a parameter added to a table appears in --help, is parsed, refused
// with --resume and recorded without another line here.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "util/param_table.h"

namespace hexgait {

// An optimizer's name and its table.
using ParamOwner = std::pair<std::string, const ParamTable*>;

class ParamFlags {
 public:
  // Adds to `command` one flag per parameter of `owners` (a name two optimizers share is one
  // flag, its help naming each with its default).
  ParamFlags(CLI::App* command, const std::vector<ParamOwner>& owners);

  // The values given on the command line (after parsing), by parameter name.
  ParamValues Given() const;
  // Every flag added ("--sigma", ...), given or not.
  std::vector<std::string> flags() const;

 private:
  CLI::App* command_;
  struct Flag {
    double value = 0;
    bool integer = false;
  };
  std::map<std::string, Flag> values_;  // by parameter name; nodes never move
};

}  // namespace hexgait
