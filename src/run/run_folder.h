// The life cycle of a resumable run's output folder, written once for `evolve`, `repertoire` and
// `sweep`: refuse a folder another command wrote, create it, hold its lock for the run,
// mark it running until the last result is written (readers refuse it meanwhile,
// run/run_state.h), and write every file atomically. Also the checks of --resume: no run flags
// beside it, a state file that is there, and the built-in creature the state records.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "util/folder_lock.h"

namespace hexgait {

class RunFolder {
 public:
  // Opens `path` (given by `flag`: "--out" or "--resume") for a run of `command`. A folder is
  // accepted when new, empty, or written by `command` (its marker, or one of `legacy_files`
  // for runs from before markers); `files` are checked as outputs before anything is written.
  RunFolder(const std::string& path, const std::string& flag, const std::string& command,
            const std::vector<std::string>& files,
            const std::vector<std::string>& legacy_files = {});
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }
  void Write(const std::string& name, const std::string& text) const;
  // Marks the folder complete: every result of this run is written.
  void Complete() const;

 private:
  std::string path_, command_;
  std::unique_ptr<FolderLock> lock_;
};

// --resume DIR: refuses `run_flags_given` (a resumed run keeps the parameters in `state_file`)
// and a folder without the state file; returns the file's path.
std::string ResumeStatePath(const std::string& dir, const std::string& state_file,
                            const std::vector<std::string>& run_flags_given);

// The built-in creature a resumable state file records ("" if none or not readable): a run of
// a built-in creature resumes without --creature.
std::string RecordedBuiltInCreature(const std::string& state_path, size_t max_bytes);
// The --damage a resumable state file records ("" if none or not readable): a damaged run
// resumes without --damage, as a built-in creature does without --creature (the fingerprint
// still refuses another damage given explicitly).
std::string RecordedDamage(const std::string& state_path, size_t max_bytes);

}  // namespace hexgait
