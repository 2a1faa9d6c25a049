#include "ga/genome_io.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

// After the layout line, marks a continuous genome: offsets in length units, not genes.
constexpr const char* kOffsetsLine = "values offsets";

std::string LayoutName(bool symmetric) {
  return symmetric ? "symmetric" : "full";
}

// Splits into whitespace-separated words, ignoring '#' comments.
std::vector<std::string> Words(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace

std::string FormatGenome(const Genome& genome, const std::string& comment) {
  const GenomeLayout& layout = genome.layout();
  std::ostringstream out;
  if (genome.continuous()) {
    out << "# hexgait genome: one real offset per (motor spring, leg position), in length units\n";
    out << "# rest length = geometric length + offset\n";
  } else {
    out << "# hexgait genome: one gene per (motor spring, leg position), an integer in ["
        << kGeneMin << ", " << kGeneMax << "]\n";
    out << "# rest length = geometric length + gene * gene_length_step (see the motor program)\n";
  }
  // A comment is one line: a line break (or any control character) in it, from a path or a
  // Python caller, becomes a space, so the file always reads back.
  std::string line = comment;
  for (char& c : line) c = static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
  if (!line.empty()) out << "# " << line << "\n";
  out << "layout " << LayoutName(layout.symmetric) << "\n";
  if (genome.continuous()) out << kOffsetsLine << "\n";
  for (int g = 0; g < genome.num_genes(); ++g) {
    out << layout.spring_name[g] << ' ' << layout.position_name[g] << ' ';
    if (genome.continuous()) {
      // 17 significant digits: the file gives back the offsets, and the run, bit for bit.
      char value[32];
      std::snprintf(value, sizeof value, "%.17g", genome.offsets()[g]);
      out << value << '\n';
    } else {
      out << genome.gene(g) << '\n';
    }
  }
  return out.str();
}

bool GenomeFileIsSymmetric(const std::string& text, const std::string& source) {
  CheckText(text, source);
  std::istringstream in(text);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::vector<std::string> words = Words(line);
    if (words.empty()) continue;
    if (words.size() == 2 && words[0] == "layout") {
      if (words[1] == "full") return false;
      if (words[1] == "symmetric") return true;
    }
    throw InputError(source + ":" + std::to_string(line_number) +
                     ": expected 'layout full' or 'layout symmetric' before the genes");
  }
  throw InputError(source + ": no genes (the file has no 'layout' line)");
}

Genome ParseGenome(const std::string& text, const std::string& source,
                   std::shared_ptr<const GenomeLayout> layout) {
  CheckText(text, source);
  Genome genome(layout);
  std::vector<double> offsets;  // filled when the file is a continuous genome
  std::vector<int> seen_on_line(layout->num_genes(), 0);
  std::istringstream in(text);
  int line_number = 0;
  bool have_layout = false;
  int count = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::string where = source + ":" + std::to_string(line_number) + ": ";
    const std::vector<std::string> words = Words(line);
    if (words.empty()) continue;
    if (!have_layout) {
      if (words.size() != 2 || words[0] != "layout" || words[1] != LayoutName(layout->symmetric)) {
        throw InputError(where + "expected 'layout " + LayoutName(layout->symmetric) + "'");
      }
      have_layout = true;
      continue;
    }
    if (count == 0 && offsets.empty() && words.size() == 2 &&
        words[0] + " " + words[1] == kOffsetsLine) {
      offsets.assign(static_cast<size_t>(layout->num_genes()), 0.0);
      continue;
    }
    if (words.size() != 3) {
      throw InputError(where + "expected '<spring> <position> <gene>', got " +
                       std::to_string(words.size()) + " words");
    }
    const int g = layout->FindGene(words[0], words[1]);
    if (g < 0) {
      throw InputError(where + "no gene for spring '" + words[0] + "' at position '" + words[1] +
                       "' in the " + LayoutName(layout->symmetric) + " layout");
    }
    if (seen_on_line[g] != 0) {
      throw InputError(where + "gene '" + words[0] + " " + words[1] + "' already given on line " +
                       std::to_string(seen_on_line[g]));
    }
    if (!offsets.empty()) {
      size_t used = 0;
      double offset = 0;
      try {
        offset = std::stod(words[2], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != words[2].size() || !std::isfinite(offset)) {
        throw InputError(where + "offset '" + words[2] + "' is not a finite number");
      }
      offsets[static_cast<size_t>(g)] = offset;
      seen_on_line[g] = line_number;
      ++count;
      continue;
    }
    size_t used = 0;
    long value = 0;
    try {
      value = std::stol(words[2], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != words[2].size()) {
      throw InputError(where + "gene value '" + words[2] + "' is not an integer");
    }
    if (value < kGeneMin || value > kGeneMax) {
      throw InputError(where + "gene value " + words[2] + " is outside [" +
                       std::to_string(kGeneMin) + ", " + std::to_string(kGeneMax) + "]");
    }
    genome.set_gene(g, static_cast<int>(value));
    seen_on_line[g] = line_number;
    ++count;
  }
  if (!have_layout) throw InputError(source + ": no genes (the file has no 'layout' line)");
  if (count != layout->num_genes()) {
    throw InputError(source + ": has " + std::to_string(count) + " genes, the " +
                     LayoutName(layout->symmetric) + " layout needs " +
                     std::to_string(layout->num_genes()));
  }
  if (!offsets.empty()) return Genome::FromOffsets(std::move(layout), offsets.data());
  return genome;
}

Genome LoadGenomeFile(const std::string& path, std::shared_ptr<const GenomeLayout> layout) {
  return ParseGenome(ReadTextFile(path), path, std::move(layout));
}

}  // namespace hexgait
