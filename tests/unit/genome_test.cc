#include <gtest/gtest.h>

#include "ga/genome.h"
#include "ga/genome_io.h"
#include "ga/rng.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

class GenomeTest : public testing::Test {
 protected:
  CreatureModel model_ = test::DefaultCreature();
  MotorProgram program_ = LoadMotorProgramOrDefault("", model_);
};

TEST(GeneCodec, TwosComplementMostSignificantBitFirst) {
  uint8_t bits[4];
  EncodeGene(-8, bits);
  EXPECT_EQ((std::vector<uint8_t>{bits, bits + 4}), (std::vector<uint8_t>{1, 0, 0, 0}));
  EncodeGene(7, bits);
  EXPECT_EQ((std::vector<uint8_t>{bits, bits + 4}), (std::vector<uint8_t>{0, 1, 1, 1}));
  EncodeGene(-1, bits);
  EXPECT_EQ((std::vector<uint8_t>{bits, bits + 4}), (std::vector<uint8_t>{1, 1, 1, 1}));
  for (int v = kGeneMin; v <= kGeneMax; ++v) {
    EncodeGene(v, bits);
    EXPECT_EQ(DecodeGene(bits), v);
  }
}

TEST_F(GenomeTest, PapersChromosomeIs480Bits) {
  const auto full = MakeGenomeLayout(model_, program_, false);
  EXPECT_EQ(full->num_genes(), 120);
  EXPECT_EQ(full->num_bits(), 480);
  const auto symmetric = MakeGenomeLayout(model_, program_, true);
  EXPECT_EQ(symmetric->num_genes(), 60);
  for (int g = 0; g < symmetric->num_genes(); ++g) {
    ASSERT_EQ(symmetric->springs_of_gene[g].size(), 2u);
  }
}

TEST_F(GenomeTest, BitsRoundTrip) {
  Genome genome(MakeGenomeLayout(model_, program_, false));
  Rng rng(42);
  for (int g = 0; g < genome.num_genes(); ++g) {
    genome.set_gene(g, kGeneMin + static_cast<int>(rng.NextBelow(16)));
  }
  Genome copy(genome.layout_ptr());
  copy.FromBits(genome.ToBits());
  EXPECT_EQ(copy, genome);
}

TEST_F(GenomeTest, FileRoundTrip) {
  for (bool symmetric : {false, true}) {
    const auto layout = MakeGenomeLayout(model_, program_, symmetric);
    Genome genome(layout);
    for (int g = 0; g < genome.num_genes(); ++g) genome.set_gene(g, (g * 7) % 16 - 8);
    const std::string text = FormatGenome(genome, "test");
    EXPECT_EQ(GenomeFileIsSymmetric(text, "t"), symmetric);
    EXPECT_EQ(ParseGenome(text, "t", layout), genome);
  }
}

// A comment with a line break (from a path or a Python caller) stays one comment line: the
// written file reads back instead of failing on the line after the break.
TEST_F(GenomeTest, ACommentWithALineBreakStillReadsBack) {
  const auto layout = MakeGenomeLayout(model_, program_, false);
  Genome genome(layout);
  genome.set_gene(3, -2);
  const std::string text = FormatGenome(genome, "from\nlayout symmetric\r\nleft_rear coxa 7");
  EXPECT_EQ(ParseGenome(text, "t", layout), genome);
  EXPECT_NE(text.find("# from layout symmetric  left_rear coxa 7\n"), std::string::npos) << text;
}

TEST_F(GenomeTest, RejectsBadFiles) {
  const auto layout = MakeGenomeLayout(model_, program_, false);
  const std::string good = FormatGenome(Genome(layout), "");
  auto expect_error = [&](const std::string& text, const std::string& expected) {
    try {
      ParseGenome(text, "g.genome", layout);
      FAIL() << "no error; expected '" << expected << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  // Drop the last gene line: wrong length.
  std::string missing = good.substr(0, good.rfind('\n', good.size() - 2) + 1);
  expect_error(missing, "has 119 genes, the full layout needs 120");
  std::string out_of_range = good;
  out_of_range.replace(out_of_range.rfind(" 0\n"), 3, " 8\n");
  expect_error(out_of_range, "gene value 8 is outside [-8, 7]");
  std::string below = good;
  below.replace(below.rfind(" 0\n"), 3, " -9\n");
  expect_error(below, "gene value -9 is outside");
  std::string not_integer = good;
  not_integer.replace(not_integer.rfind(" 0\n"), 3, " 1.5\n");
  expect_error(not_integer, "is not an integer");
  const std::string first_gene = good.substr(good.find("layout full\n") + 12);
  expect_error(good + first_gene.substr(0, first_gene.find('\n') + 1), "already given on line");
  expect_error("layout full\nnot_a_spring swing 1\n", "no gene for spring 'not_a_spring'");
  expect_error("layout symmetric\n", "expected 'layout full'");
  expect_error("# only a comment\n", "no genes");
}

}  // namespace
}  // namespace hexgait
