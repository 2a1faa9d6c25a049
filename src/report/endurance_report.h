// The files of `hexgait endurance` (study/endurance.h): one CSV row per run, the survival
// curves as CSV and as a figure (gnuplot), and the Markdown tables of the README.
#pragma once

#include <span>
#include <string>

#include "study/endurance.h"

namespace hexgait {

// Writes into `dir` (which must exist): endurance.csv, survival.csv, survival.gp, survival.png,
// survival.svg and table.md. Returns table.md's text. Throws InputError (gnuplot missing or
// failing, a file that cannot be written).
std::string WriteEnduranceReport(const std::string& dir, std::span<const EnduranceGait> gaits,
                                 const EnduranceSettings& settings, const EnduranceResult& result);

// The gait groups in order of first appearance.
std::vector<std::string> EnduranceGroups(std::span<const EnduranceGait> gaits);

}  // namespace hexgait
