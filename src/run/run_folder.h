// The checks of --resume for the resumable runs (`evolve`, `repertoire`, `sweep`, whose folders
// are util/output.h's ResumableFolder): no run flags beside it, a state file that is there, and
// the built-in creature and damage the state records.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "util/output.h"

namespace hexgait {

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
