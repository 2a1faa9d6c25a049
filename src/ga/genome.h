// A genome: one 4-bit integer in [-8, 7] per (motor spring, leg position), perturbing that
// position's geometric rest length. The chromosome is the genes' two's-complement bits,
// most significant bit first: 20 springs x 6 positions x 4 bits = 480 bits by default.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/creature.h"
#include "motor/leg_targets.h"
#include "motor/motor_program.h"

namespace hexgait {

inline constexpr int kGeneBits = 4;
inline constexpr int kGeneMin = -8;
inline constexpr int kGeneMax = 7;

// Which springs and position each gene drives. With `symmetric`, one gene drives a right-leg
// spring and its mirror on the left leg (60 genes instead of 120).
struct GenomeLayout {
  bool symmetric = false;
  std::vector<std::vector<int>> springs_of_gene;  // 1 spring, or 2 when symmetric
  std::vector<int> position_of_gene;
  std::vector<std::string> spring_name;    // of the gene's first spring
  std::vector<std::string> position_name;  // of the gene's position

  int num_genes() const { return static_cast<int>(position_of_gene.size()); }
  int num_bits() const { return num_genes() * kGeneBits; }
  int FindGene(const std::string& spring, const std::string& position) const;  // -1 if none
};

std::shared_ptr<const GenomeLayout> MakeGenomeLayout(const CreatureModel& model,
                                                     const MotorProgram& program, bool symmetric);

// A genome is discrete (the paper's: 4-bit genes, what the GA and MAP-Elites breed) or
// continuous (a real rest-length offset per gene, in length units: what CMA-ES proposes). Both
// decode through PerturbedRestLengths and are stored in the same file format (ga/genome_io.h),
// so `simulate`, `movie` and `endurance` run either.
class Genome {
 public:
  explicit Genome(std::shared_ptr<const GenomeLayout> layout);  // all genes zero
  // A continuous genome: offsets[g] length units on gene g's springs, g < num_genes().
  static Genome FromOffsets(std::shared_ptr<const GenomeLayout> layout, const double* offsets);

  const GenomeLayout& layout() const { return *layout_; }
  const std::shared_ptr<const GenomeLayout>& layout_ptr() const { return layout_; }
  int num_genes() const { return static_cast<int>(genes_.size()); }
  int gene(int i) const { return genes_[i]; }
  void set_gene(int i, int value);  // asserts value in [-8, 7]
  const std::vector<int8_t>& genes() const { return genes_; }
  bool continuous() const { return !offsets_.empty(); }
  // A continuous genome's offsets (length units); empty for a discrete one.
  const std::vector<double>& offsets() const { return offsets_; }
  // Gene g's offset in length units, for either kind: gene * step for a discrete genome.
  double Offset(int g, double gene_length_step) const {
    return continuous() ? offsets_[g] : genes_[g] * gene_length_step;
  }

  // Discrete genomes only.
  std::vector<uint8_t> ToBits() const;              // 0/1 per bit
  void FromBits(const std::vector<uint8_t>& bits);  // size must be num_bits()

  bool operator==(const Genome& other) const {
    return genes_ == other.genes_ && offsets_ == other.offsets_;
  }

 private:
  std::shared_ptr<const GenomeLayout> layout_;
  std::vector<int8_t> genes_;    // all zero for a continuous genome
  std::vector<double> offsets_;  // empty for a discrete genome
};

// The genome's decoding: the geometric lengths (motor/leg_targets.h) perturbed by each gene
// (gene * gene_length_step). Everything below the GA takes these tables, never a genome.
// Throws InputError if a perturbed length would be non-positive.
RestLengthTable PerturbedRestLengths(const CreatureModel& model, const MotorProgram& program,
                                     const Genome& genome);
// The same from the geometric table computed once (GeometricRestLengths(model, program)), for
// a population: the geometry is the costly part of the decoding.
RestLengthTable PerturbedRestLengths(const RestLengthTable& geometric, const CreatureModel& model,
                                     const MotorProgram& program, const Genome& genome);

// The continuous decoding, for optimizers that propose lengths rather than genes (CMA-ES from
// Python): the geometric lengths plus offsets[g] length units on gene g's springs, g <
// layout.num_genes(). With offsets[g] = gene * gene_length_step it gives PerturbedRestLengths's
// bits. Throws InputError for a non-finite offset or a non-positive length.
RestLengthTable OffsetRestLengths(const RestLengthTable& geometric, const CreatureModel& model,
                                  const GenomeLayout& layout, const double* offsets);

// Two's-complement 4-bit codec, exposed for tests.
void EncodeGene(int value, uint8_t* bits4);
int DecodeGene(const uint8_t* bits4);

}  // namespace hexgait
