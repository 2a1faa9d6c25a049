// One error type for everything a user can get wrong: files, flags and numbers.
// The message is a single line naming what is wrong; main() prints it and exits non-zero.
// Simulation code never throws: it reports divergence through its result struct.
#pragma once

#include <stdexcept>
#include <string>

namespace hexgait {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace hexgait
