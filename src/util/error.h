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

// An InputError about a file itself rather than its content: missing, a folder, not a regular
// file, unreadable, unwritable. The command line prints it like any other; the Python module
// raises OSError for it (ValueError for the rest).
class FileError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace hexgait
