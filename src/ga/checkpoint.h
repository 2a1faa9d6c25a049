// A GA checkpoint: everything needed to continue an evolution after its last completed
// generation and get the same bits as a run that was never interrupted. The random streams
// are derived from (seed, generation), so no generator state has to be saved; the population
// with its exact fitnesses and results, the history and the best-so-far do.
//
// Stored as JSON (doubles written with 17 significant digits, which round-trip exactly) with a
// fingerprint of the creature and motor program, so a checkpoint is never continued with
// different physics or parameters.
#pragma once

#include <cstdint>
#include <string>

#include "ga/evolution.h"

namespace hexgait {

inline constexpr int kCheckpointVersion = 1;

// A hash of everything in the creature and motor program that can change a fitness.
uint64_t SceneFingerprint(const CreatureModel& model, const MotorProgram& program);

// `creature`, when not empty, is recorded as the run's --creature (a built-in name or a path),
// so a resumed run can reload a built-in creature by name.
std::string FormatCheckpoint(const EvolutionCheckpoint& checkpoint, uint64_t scene_fingerprint,
                             const std::string& creature = "");
// The creature a checkpoint records ("" when none, or when `text` is not a JSON object).
std::string CheckpointCreature(const std::string& text);

// Parses and validates a checkpoint for this scene (throws InputError naming `source` and the
// problem). The parameters are taken from the checkpoint, except `threads`, which does not
// change results.
EvolutionCheckpoint ParseCheckpoint(const std::string& text, const std::string& source,
                                    const CreatureModel& model, const MotorProgram& program);

}  // namespace hexgait
