#include "ga/genome.h"

#include <cassert>
#include <cmath>
#include <string>

#include "ga/genome_eval.h"
#include "util/error.h"

namespace hexgait {

int GenomeLayout::FindGene(const std::string& spring, const std::string& position) const {
  for (int g = 0; g < num_genes(); ++g) {
    if (spring_name[g] == spring && position_name[g] == position) return g;
  }
  return -1;
}

std::shared_ptr<const GenomeLayout> MakeGenomeLayout(const CreatureModel& model,
                                                     const MotorProgram& program, bool symmetric) {
  auto layout = std::make_shared<GenomeLayout>();
  layout->symmetric = symmetric;
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    const Leg& l = model.legs[leg];
    if (symmetric && l.side != Side::kRight) continue;
    for (size_t k = 0; k < l.springs.size(); ++k) {
      std::vector<int> springs = {l.springs[k]};
      // The mirror leg's k-th spring is this spring's mirror image (checked by the asset tests).
      if (symmetric) springs.push_back(model.legs[l.mirror].springs[k]);
      for (int p = 0; p < program.num_positions(); ++p) {
        layout->springs_of_gene.push_back(springs);
        layout->position_of_gene.push_back(p);
        layout->spring_name.push_back(model.spring_names[l.springs[k]]);
        layout->position_name.push_back(program.positions[p].name);
      }
    }
  }
  return layout;
}

Genome::Genome(std::shared_ptr<const GenomeLayout> layout)
    : layout_(std::move(layout)), genes_(layout_->num_genes(), 0) {}

Genome Genome::FromOffsets(std::shared_ptr<const GenomeLayout> layout, const double* offsets) {
  Genome genome(std::move(layout));
  genome.offsets_.assign(offsets, offsets + genome.num_genes());
  return genome;
}

void Genome::set_gene(int i, int value) {
  assert(value >= kGeneMin && value <= kGeneMax);
  assert(!continuous());
  genes_[i] = static_cast<int8_t>(value);
}

void EncodeGene(int value, uint8_t* bits4) {
  const unsigned u = static_cast<unsigned>(value) & 0xFu;
  for (int b = 0; b < kGeneBits; ++b) bits4[b] = (u >> (kGeneBits - 1 - b)) & 1u;
}

int DecodeGene(const uint8_t* bits4) {
  unsigned u = 0;
  for (int b = 0; b < kGeneBits; ++b) u = (u << 1) | (bits4[b] & 1u);
  return u >= 8 ? static_cast<int>(u) - 16 : static_cast<int>(u);
}

std::vector<uint8_t> Genome::ToBits() const {
  assert(!continuous());
  std::vector<uint8_t> bits(genes_.size() * kGeneBits);
  for (size_t g = 0; g < genes_.size(); ++g) EncodeGene(genes_[g], &bits[g * kGeneBits]);
  return bits;
}

void Genome::FromBits(const std::vector<uint8_t>& bits) {
  assert(bits.size() == genes_.size() * kGeneBits);
  for (size_t g = 0; g < genes_.size(); ++g) {
    genes_[g] = static_cast<int8_t>(DecodeGene(&bits[g * kGeneBits]));
  }
}

RestLengthTable PerturbedRestLengths(const RestLengthTable& geometric, const CreatureModel& model,
                                     const MotorProgram& program, const Genome& genome) {
  const GenomeLayout& layout = genome.layout();
  if (genome.continuous())
    return OffsetRestLengths(geometric, model, layout, genome.offsets().data());
  RestLengthTable table = geometric;
  for (int g = 0; g < layout.num_genes(); ++g) {
    const int value = genome.gene(g);
    if (value == 0) continue;
    for (int s : layout.springs_of_gene[g]) {
      if (model.locked(s)) continue;  // a locked leg ignores its genes (model/damage.h)
      double& length = table.length[layout.position_of_gene[g] * table.num_springs + s];
      length += value * program.gene_length_step;
      if (!(length > 0)) {
        throw InputError("gene " + std::to_string(g) + " makes the rest length of spring '" +
                         model.spring_names[s] + "' non-positive");
      }
    }
  }
  return table;
}

RestLengthTable OffsetRestLengths(const RestLengthTable& geometric, const CreatureModel& model,
                                  const GenomeLayout& layout, const double* offsets) {
  RestLengthTable table = geometric;
  for (int g = 0; g < layout.num_genes(); ++g) {
    const double offset = offsets[g];
    if (!std::isfinite(offset)) {
      throw InputError("offset " + std::to_string(g) + " is not a finite number");
    }
    if (offset == 0) continue;
    for (int s : layout.springs_of_gene[g]) {
      if (model.locked(s)) continue;
      double& length = table.length[layout.position_of_gene[g] * table.num_springs + s];
      length += offset;
      if (!(length > 0)) {
        throw InputError("offset " + std::to_string(g) + " makes the rest length of spring '" +
                         model.spring_names[s] + "' non-positive");
      }
    }
  }
  return table;
}

RestLengthTable PerturbedRestLengths(const CreatureModel& model, const MotorProgram& program,
                                     const Genome& genome) {
  return PerturbedRestLengths(GeometricRestLengths(model, program), model, program, genome);
}

std::vector<RestLengthTable> PerturbedRestLengths(const CreatureModel& model,
                                                  const MotorProgram& program,
                                                  const std::vector<const Genome*>& genomes) {
  const RestLengthTable geometric = GeometricRestLengths(model, program);
  std::vector<RestLengthTable> tables;
  tables.reserve(genomes.size());
  for (const Genome* genome : genomes)
    tables.push_back(PerturbedRestLengths(geometric, model, program, *genome));
  return tables;
}

}  // namespace hexgait
