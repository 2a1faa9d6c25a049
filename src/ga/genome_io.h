// Genome files: readable text, one gene per line, naming its spring and position:
//
//   # hexgait genome
//   layout full
//   right_rear.hip_low  swing  -3
//   ...
#pragma once

#include <string>

#include "ga/genome.h"

namespace hexgait {

std::string FormatGenome(const Genome& genome, const std::string& comment);
// Parses a genome for `layout`; errors name the file and line.
Genome ParseGenome(const std::string& text, const std::string& source,
                   std::shared_ptr<const GenomeLayout> layout);
Genome LoadGenomeFile(const std::string& path, std::shared_ptr<const GenomeLayout> layout);
// "full" or "symmetric", read from a genome file's layout line (so the right layout can be
// built before parsing); throws InputError if the line is missing.
bool GenomeFileIsSymmetric(const std::string& text, const std::string& source);

}  // namespace hexgait
