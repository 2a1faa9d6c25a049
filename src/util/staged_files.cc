// StagedFiles and ScratchFiles (util/output.h): files registered in util/temp_registry for as
// long as they may be left half-written.
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "util/error.h"
#include "util/output.h"
#include "util/temp_registry.h"

namespace hexgait {

StagedFiles::StagedFiles(std::string dir) : dir_(std::move(dir)) {}

StagedFiles::~StagedFiles() {
  for (const std::string& name : names_) std::remove(Staged(name).c_str());
  for (int handle : handles_) UnregisterTemp(handle);
}

std::string StagedFiles::Staged(const std::string& name) const {
  return dir_ + name + ".staged." + std::to_string(::getpid()) +
         std::filesystem::path(name).extension().string();
}

std::string StagedFiles::Stage(const std::string& name) {
  names_.push_back(name);
  handles_.push_back(RegisterTemp(Staged(name)));
  return Staged(name);
}

void StagedFiles::CommitAll() {
  CommitTemp([&] {
    for (const std::string& name : names_) {
      if (std::rename(Staged(name).c_str(), (dir_ + name).c_str()) != 0) {
        throw FileError("cannot rename the finished " + name + " into place in " + dir_);
      }
    }
    names_.clear();
  });
}

ScratchFiles::ScratchFiles(const std::vector<std::string>& paths) : paths_(paths) {
  for (const std::string& path : paths) handles_.push_back(RegisterTemp(path));
}

ScratchFiles::~ScratchFiles() {
  for (size_t i = 0; i < paths_.size(); ++i) {
    std::remove(paths_[i].c_str());
    UnregisterTemp(handles_[i]);
  }
}

}  // namespace hexgait
