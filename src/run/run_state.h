// Whether an evolve folder holds one finished run. evolve writes its results (fitness.csv,
// best.genome, run.json) only at the end, so a run interrupted over an older run's folder
// leaves its new checkpoint beside the older run's results. The folder's marker file says which:
// evolve sets it to "running" before it writes anything and to "complete" after the last
// result, and every command that reads a run folder refuses one still marked "running".
#pragma once

#include <string>

#include "util/output.h"  // RefuseUnfinishedRun

namespace hexgait {

// Marks a folder evolve wrote, so a later run may write over it.
inline constexpr const char* kEvolveMarker = ".hexgait-evolve";
// The same for repertoire (resumable the same way).
inline constexpr const char* kRepertoireMarker = ".hexgait-repertoire";

// The records those folders hold, as every writer and reader names them.
inline constexpr const char* kRunRecordFile = "run.json";          // evolve's results
inline constexpr const char* kCheckpointFile = "checkpoint.json";  // evolve's resumable state
inline constexpr const char* kArchiveFile = "archive.json";        // repertoire's archive
inline constexpr const char* kOutputsFile = "outputs.json";        // repertoire's output choices
inline constexpr const char* kAdaptRecordFile = "adapt.json";      // adapt's summary

// Throws InputError naming `flag` unless `folder` is a folder ("no such folder", "is a file").
void RequireFolder(const std::string& folder, const std::string& flag);

// FOLDER/best.genome of a finished evolve folder (RefuseUnfinishedRun); throws InputError naming
// `flag` when there is none.
std::string FinishedRunGenome(const std::string& folder, const std::string& flag);

}  // namespace hexgait
