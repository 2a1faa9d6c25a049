#include "report/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "util/error.h"

extern char** environ;

namespace hexgait {
namespace {

// posix_spawn's C resources, released whatever happens.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
};

std::string FirstErrorLine(const std::string& log_path) {
  std::ifstream in(log_path);
  std::string line, first;
  // gnuplot prints the offending line, a caret, then '"file" line N: message'.
  while (std::getline(in, line)) {
    if (line.find("line ") != std::string::npos && line.find(':') != std::string::npos) {
      return line;
    }
    if (first.empty() && !line.empty()) first = line;
  }
  return first.empty() ? "no message" : first;
}

}  // namespace

std::string GnuplotQuote(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') {
      out += "\\n";  // gnuplot's own escape: a line break in titles and labels
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string GnuplotText(const std::string& text) {
  // In gnuplot's double-quoted source, "\\_" is the string \_, which enhanced text prints as
  // a plain underscore; a literal backslash needs four.
  std::string out = "\"";
  for (char c : text) {
    if (c == '_' || c == '^' || c == '@' || c == '&' || c == '{' || c == '}') {
      out += "\\\\";
      out += c;
    } else if (c == '\\') {
      out += "\\\\\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '"') {
      out += "\\\"";
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string GnuplotScript(const std::string& name, const std::string& description,
                          const std::string& body, const std::string& command) {
  std::ostringstream s;
  s << "# " << name << ".gp: " << description << "\n"
    << "# Written by '" << command << "'; redraw " << name << ".png and " << name
    << ".svg with: gnuplot " << name << ".gp\n"
    << "do for [format in 'png svg'] {\n"
    // Each pass starts from the same settings, whatever the previous one changed.
    << "  reset\n"
    << "  set datafile separator ','\n"
    << "  set encoding utf8\n"
    << "  set border linewidth 1.2\n"
    << "  set grid linecolor rgb '#d8d8d8' linewidth 1\n"
    << "  set key opaque box linecolor rgb '#bbbbbb' samplen 2.5 spacing 1.1\n"
    << "  if (format eq 'png') {\n"
    << "    set terminal pngcairo size " << kFigureWidth << "," << kFigureHeight
    << " enhanced font 'DejaVu Sans,15' linewidth 1.5 background '#ffffff'\n"
    << "    set output '" << name << ".png'\n"
    << "  } else {\n"
    << "    set terminal svg size " << kFigureWidth << "," << kFigureHeight
    << " enhanced font 'DejaVu Sans,15' linewidth 1.5 background '#ffffff'\n"
    << "    set output '" << name << ".svg'\n"
    << "  }\n"
    << body << "  set output\n"
    << "}\n";
  return s.str();
}

namespace {

const char kGnuplotMissing[] =
    "gnuplot not found on PATH: the figures need it; install Debian's gnuplot-nox "
    "(scripts/deps.sh does)";

}  // namespace

void CheckGnuplotFound() {
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "";
  size_t start = 0;
  while (start <= folders.size()) {
    size_t end = folders.find(':', start);
    if (end == std::string::npos) end = folders.size();
    // An empty entry is the current folder, as posix_spawnp reads PATH.
    const std::string folder = end > start ? folders.substr(start, end - start) : ".";
    const std::string file = folder + "/gnuplot";
    struct stat info {};
    if (::stat(file.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
        ::access(file.c_str(), X_OK) == 0) {
      return;
    }
    start = end + 1;
  }
  throw SystemError(kGnuplotMissing);
}

void RunGnuplot(const std::string& folder, const std::string& script) {
  const std::string log_path = folder + "/." + script + ".log";
  FileActions files;
  posix_spawn_file_actions_addchdir_np(&files.actions, folder.c_str());
  posix_spawn_file_actions_addopen(&files.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  // The log path is absolute or relative to our folder, not gnuplot's, so open it here.
  const int log_fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0) {
    throw InputError("cannot create '" + log_path + "': " + std::strerror(errno));
  }
  posix_spawn_file_actions_adddup2(&files.actions, log_fd, STDERR_FILENO);
  std::string program = "gnuplot";
  std::string argument = script;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, "gnuplot", &files.actions, nullptr, argv, environ);
  ::close(log_fd);
  if (spawn_error != 0) {
    std::remove(log_path.c_str());
    if (spawn_error == ENOENT) throw SystemError(kGnuplotMissing);
    throw SystemError("cannot start gnuplot: " + std::string(std::strerror(spawn_error)));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR)
      throw SystemError("waiting for gnuplot: " + std::string(std::strerror(errno)));
  }
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  const std::string message = ok ? "" : FirstErrorLine(log_path);
  std::remove(log_path.c_str());
  if (!ok) {
    throw SystemError("gnuplot failed on " + folder + "/" + script + ": " + message);
  }
}

}  // namespace hexgait
