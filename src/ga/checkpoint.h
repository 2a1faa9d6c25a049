// A GA checkpoint: everything needed to continue an evolution after its last completed
// generation and get the same bits as a run that was never interrupted. The random streams
// are derived from (seed, generation), so no generator state has to be saved; the population
// with its exact fitnesses and results, the history and the best-so-far do.
//
// Stored as JSON (doubles written with 17 significant digits, which round-trip exactly) with a
// fingerprint of the creature and motor program, so a checkpoint is never continued with
// different physics or parameters. Version 2 adds a checksum (FNV-1a over the compact JSON of
// everything else), so an edited or damaged file is refused rather than continued; on reading,
// the content must also be consistent (finite fitnesses equal to their results', history that
// matches the population, evaluation counts that add up).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ga/evolution.h"
#include "util/json_file.h"

namespace hexgait {

inline constexpr int kCheckpointVersion = 2;

// A checkpoint holds the whole population: about 1.3 KB per individual, so 130 MB at the
// largest population (100,000). Far above the data-file limit, and checked when writing, so
// everything evolve writes, evolve --resume can read.
inline constexpr size_t kMaxCheckpointBytes = size_t{512} << 20;

// A generational search's history in its checkpoint (the GA's and CMA-ES's): one object per
// completed generation, exact doubles. ReadHistory requires `generations` entries.
nlohmann::json HistoryJson(const std::vector<GenerationStats>& history);
std::vector<GenerationStats> ReadHistory(const JsonReader& history, int generations);

// A generational search's parameters in its checkpoint (the GA's and CMA-ES's): the shared
// ones and the optimizer's own settings as members of one object, and back (any member that is
// not a shared one is a setting, checked by the optimizer against its table).
nlohmann::json EvolutionParamsJson(const EvolutionParams& params);
EvolutionParams ReadEvolutionParams(const JsonReader& r);

// A hash of everything in the creature and motor program that can change a fitness.
uint64_t SceneFingerprint(const CreatureModel& model, const MotorProgram& program);
// The fingerprint a checkpoint (the GA's or CMA-ES's) records, as written there; "" when the
// text is not a checkpoint or has none.
std::string CheckpointSceneFingerprint(const std::string& text);

// `creature`, when not empty, is recorded as the run's --creature (a built-in name or a path),
// so a resumed run can reload a built-in creature by name; `damage`, when not empty, as its
// --damage (the fingerprint already covers it; this is for the reader).
std::string FormatCheckpoint(const EvolutionCheckpoint& checkpoint, uint64_t scene_fingerprint,
                             const std::string& creature = "", const std::string& damage = "");
// The creature a checkpoint records ("" when none, or when `text` is not a JSON object).
std::string CheckpointCreature(const std::string& text);
// The --damage a checkpoint or archive records ("" when none, or when `text` is not a JSON
// object).
std::string CheckpointDamage(const std::string& text);

// Parses and validates a checkpoint for this scene (throws InputError naming `source` and the
// problem). The parameters are taken from the checkpoint, except `threads`, which does not
// change results. A version 1 checkpoint (before checksums) is accepted after the consistency
// checks; `*unchecked` is set to true for it, so the caller can warn that edits to it cannot
// be detected.
EvolutionCheckpoint ParseCheckpoint(const std::string& text, const std::string& source,
                                    const CreatureModel& model, const MotorProgram& program,
                                    bool* unchecked = nullptr);

}  // namespace hexgait
