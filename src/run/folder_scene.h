// A run's scene travels with its folder. Every command that consumes a folder another command
// wrote (an evolve run's --run, a sweep's --runs, a repertoire's --repertoire) takes the
// creature, motor program, damage, step and integrator from the folder's record through
// SceneOfFolders, never from the defaults: a run evolved on a damaged creature is replayed,
// filmed, tested and drawn on that damaged creature. A flag the user gives that contradicts the
// record is refused; LoadScene then refuses a creature or motor file whose content has changed
// since the run (the record's scene fingerprint).
#pragma once

#include <string>
#include <vector>

#include "run/scene.h"

namespace hexgait {

// What a folder's record says about the scene that made it.
struct RecordedScene {
  SceneOptions options;     // creature, motor, damage, dt and integrator; no flags given
  std::string precision;    // what its evaluations ran in ("double", "float")
  std::string fingerprint;  // SceneFingerprint in hex; "" in records written before it
  std::string record;       // the record's path, for messages
};

// A folder and the flag that named it ("--run", "--runs", "--repertoire").
struct FolderArg {
  std::string flag;
  std::string dir;
};

// The record of an evolve folder (run.json), a repertoire folder (archive.json) or an adapt
// folder (adapt.json: the intact scene of the repertoire it adapted, whose damage it records
// apart); throws InputError naming `flag` and `dir` when the folder holds none of them or the
// record is unreadable.
RecordedScene ReadRecordedScene(const FolderArg& folder);

// The scene options to consume `folders` with: their recorded scene (all of them must record
// the same one), with --allow-long from `flags`. Each scene flag the user gave (flags.given)
// must agree with the record, or InputError names the flag, the folder and both values. With
// no folders, `flags` unchanged.
SceneOptions SceneOfFolders(const SceneOptions& flags, const std::vector<FolderArg>& folders);

}  // namespace hexgait
