// A MAP-Elites run on disk: its parameters, every elite (genes, exact result, the evaluation
// that found it) and the history, enough for `hexgait repertoire --resume` to continue after
// the last completed batch with the same bits as a run never interrupted. The same file is the
// finished run's archive. JSON with doubles that round-trip, a scene fingerprint (never
// continued with other physics) and a checksum (never continued after an edit); on reading,
// every elite must also sit in the cell its result's behaviour names and be a standing gait.
#pragma once

#include <cstdint>
#include <string>

#include "ga/map_elites.h"

namespace hexgait {

inline constexpr int kArchiveVersion = 1;
// About 1 KB per elite: a full 5^6 archive is 16 MB; the largest allowed archive (1,000,000
// cells) would need 1 GB, refused when written.
inline constexpr size_t kMaxArchiveBytes = size_t{512} << 20;

std::string FormatArchive(const MapElitesState& state, uint64_t scene_fingerprint,
                          const std::string& creature = "", const std::string& damage = "");
// Throws InputError naming `source` and the problem.
MapElitesState ParseArchive(const std::string& text, const std::string& source,
                            const CreatureModel& model, const MotorProgram& program);

// A genome as one hex digit per gene (its 4 bits), the compact form the archive stores.
std::string GenesHex(const Genome& genome);

}  // namespace hexgait
