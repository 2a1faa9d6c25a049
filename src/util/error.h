// The error types: InputError for everything a user can get wrong (files, flags and numbers),
// SystemError for what fails in the machine around a correct input (a library that will not
// load, no OpenGL context, the encoder refusing a call). The message is a single line naming what
// is wrong; main() prints it and exits non-zero, with a different status for each type so a
// script can tell "fix your input" from "fix this machine".
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

// Not the user's input but the environment or a library at run time: FFmpeg or a GL library
// that cannot be loaded, an OpenGL context that cannot be made, an avcodec call that fails on a
// valid frame. The command line exits with status 4 (InputError: 1); the Python module raises
// RuntimeError.
class SystemError : public std::runtime_error {
 public:
  explicit SystemError(const std::string& message) : std::runtime_error(message) {}
};

// A file that was checked writable and opened, then could not be written whole: a full disk, a
// quota, an I/O error. The machine's, not the input's: exit status 4 like any SystemError; the
// Python module raises OSError for it, as for a FileError.
class StorageError : public SystemError {
 public:
  using SystemError::SystemError;
};

}  // namespace hexgait
