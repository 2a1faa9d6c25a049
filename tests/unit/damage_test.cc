// Damage as data (model/damage.h): parsing and its errors, the text round trip, what each kind
// does to the creature and its rest-length tables, that it changes a run, and that the scalar
// and batched paths still agree bit for bit on a damaged creature.
#include "model/damage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ga/checkpoint.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/assets.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "same_result.h"
#include "sim/evaluate.h"
#include "sim/state.h"
#include "sim/trace.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

CreatureModel Damaged(const std::string& spec) {
  CreatureModel model = test::DefaultCreature();
  ApplyDamage(ParseDamage(spec, model), &model);
  return model;
}

std::string ErrorOf(const std::string& spec) {
  const CreatureModel model = test::DefaultCreature();
  try {
    ParseDamage(spec, model);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(Damage, ParsesEachKindAndWritesItBack) {
  const CreatureModel model = test::DefaultCreature();
  const std::string text = "right_front:weak=0.2,left_rear:locked,right_middle:short=0.75";
  const CreatureDamage d = ParseDamage(text, model);
  ASSERT_EQ(d.legs.size(), 3u);
  EXPECT_EQ(d.legs[0].leg, model.LegIndex("right_front"));
  EXPECT_EQ(d.legs[0].kind, DamageKind::kWeak);
  EXPECT_EQ(d.legs[0].factor, 0.2);
  EXPECT_EQ(d.legs[1].leg, model.LegIndex("left_rear"));
  EXPECT_EQ(d.legs[1].kind, DamageKind::kLocked);
  EXPECT_EQ(d.legs[2].kind, DamageKind::kShort);
  EXPECT_EQ(d.legs[2].factor, 0.75);
  EXPECT_EQ(DamageText(d, model), text);
  // Factors are written in their shortest round-trip form, so the text reads back the same.
  const CreatureDamage odd = ParseDamage("left_front:weak=0.1234567890123", model);
  EXPECT_EQ(ParseDamage(DamageText(odd, model), model).legs[0].factor, odd.legs[0].factor);
  // Two kinds on one leg are one leg damaged twice over, which is allowed.
  EXPECT_EQ(ParseDamage("left_front:weak=1,left_front:locked", model).legs.size(), 2u);
  EXPECT_TRUE(ParseDamage("", model).empty());
  EXPECT_EQ(DamageText(CreatureDamage{}, model), "");
}

TEST(Damage, RefusesBadInputWithOneLineNamingIt) {
  EXPECT_EQ(ErrorOf("right_fornt:weak=0.2"),
            "--damage entry 'right_fornt:weak=0.2': unknown leg 'right_fornt' (legs: "
            "right_rear, right_middle, right_front, left_rear, left_middle, left_front)");
  EXPECT_EQ(ErrorOf("right_front:broken"),
            "--damage entry 'right_front:broken': unknown kind 'broken' (kinds: weak=F, locked, "
            "short=F, lost)");
  EXPECT_EQ(ErrorOf("right_front"),
            "--damage entry 'right_front' must be LEG:KIND (kinds: weak=F, locked, short=F, lost)");
  EXPECT_EQ(ErrorOf("right_front:weak"),
            "--damage entry 'right_front:weak': weak needs a factor (weak=F, F in [0.01, 1])");
  EXPECT_EQ(ErrorOf("right_front:weak="),
            "--damage entry 'right_front:weak=': weak needs a factor (weak=F, F in [0.01, 1])");
  EXPECT_EQ(ErrorOf("right_front:weak=abc"),
            "--damage entry 'right_front:weak=abc': factor 'abc' is not a number");
  EXPECT_EQ(ErrorOf("right_front:weak=0.2x"),
            "--damage entry 'right_front:weak=0.2x': factor '0.2x' is not a number");
  EXPECT_EQ(ErrorOf("right_front:weak=nan"),
            "--damage entry 'right_front:weak=nan': factor 'nan' is not a number");
  EXPECT_EQ(ErrorOf("right_front:weak=0"),
            "--damage entry 'right_front:weak=0': factor 0 is outside [0.01, 1] for weak");
  // A stiffness below a hundredth is a severed leg in all but name (5e-324: lost in rounding).
  EXPECT_EQ(
      ErrorOf("right_front:weak=5e-324"),
      "--damage entry 'right_front:weak=5e-324': factor 5e-324 is outside [0.01, 1] for weak");
  EXPECT_EQ(ErrorOf("right_front:weak=1.5"),
            "--damage entry 'right_front:weak=1.5': factor 1.5 is outside [0.01, 1] for weak");
  EXPECT_EQ(ErrorOf("right_front:short=0.4"),
            "--damage entry 'right_front:short=0.4': factor 0.4 is outside [0.5, 1] for short");
  EXPECT_EQ(ErrorOf("right_front:locked=0.5"),
            "--damage entry 'right_front:locked=0.5': locked takes no factor");
  EXPECT_EQ(ErrorOf("right_front:weak=0.2,right_front:weak=0.5"),
            "--damage damages leg right_front twice with weak");
  EXPECT_EQ(ErrorOf("right_front:locked,"), "--damage 'right_front:locked,' has an empty entry");
  EXPECT_EQ(ErrorOf("right_front:short=0.5"), "(accepted)");  // the range's ends are in it
  EXPECT_EQ(ErrorOf("right_front:weak=1"), "(accepted)");
}

TEST(Damage, ALibraryIsEveryLegWithEachKind) {
  const CreatureModel model = test::DefaultCreature();
  const std::vector<std::string> library = DamageLibrary(model, DefaultDamageLibraryKinds());
  ASSERT_EQ(library.size(), model.legs.size() * DefaultDamageLibraryKinds().size());
  EXPECT_EQ(library.front(), "right_rear:" + DefaultDamageLibraryKinds().front());
  EXPECT_EQ(library.back(), "left_front:" + DefaultDamageLibraryKinds().back());
  for (const std::string& damage : library) {
    EXPECT_EQ(DamageText(ParseDamage(damage, model), model), damage);
  }
  EXPECT_EQ(DamageLibrary(model, {"short=0.80"})[1], "right_middle:short=0.8");
  EXPECT_TRUE(DamageLibrary(model, {}).empty());
  const auto error_of = [&](const std::string& kind) {
    try {
      DamageLibrary(model, {kind});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error_of("right_front:weak=0.2"),
            "library kind 'right_front:weak=0.2': one injury without its leg, e.g. weak=0.2 "
            "(every leg gets it)");
  EXPECT_EQ(error_of("weak=2"),
            "library kind 'weak=2': --damage entry 'right_rear:weak=2': factor 2 is outside "
            "[0.01, 1] for weak");
}

TEST(Damage, WeakScalesOnlyThatLegsMotorSprings) {
  const CreatureModel intact = test::DefaultCreature();
  const CreatureModel model = Damaged("right_front:weak=0.2");
  const std::vector<int>& leg = intact.legs[intact.LegIndex("right_front")].springs;
  for (int s = 0; s < intact.num_springs(); ++s) {
    const bool hit = std::find(leg.begin(), leg.end(), s) != leg.end();
    EXPECT_EQ(model.stiffness[s], hit ? intact.stiffness[s] * 0.2 : intact.stiffness[s]) << s;
    EXPECT_EQ(model.damping[s], hit ? intact.damping[s] * 0.2 : intact.damping[s]) << s;
    EXPECT_EQ(model.rest_length[s], intact.rest_length[s]);
  }
  EXPECT_EQ(model.damage, "right_front:weak=0.2");
}

// A locked leg's springs hold their rest lengths in every position and whatever the genes say;
// the genome keeps its layout, so a repertoire's genomes still run on the damaged creature.
TEST(Damage, LockedLegKeepsItsRestLengthsUnderAnyProgram) {
  const CreatureModel model = Damaged("left_rear:locked");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  const CreatureModel intact = test::DefaultCreature();
  EXPECT_EQ(MakeGenomeLayout(model, program, false)->num_genes(),
            MakeGenomeLayout(intact, program, false)->num_genes());
  const Genome genome = test::RandomGenome(model, program, 7);
  const RestLengthTable table = PerturbedRestLengths(model, program, genome);
  const std::vector<int>& locked = model.legs[model.LegIndex("left_rear")].springs;
  for (int p = 0; p < table.num_positions; ++p) {
    for (int s : locked) EXPECT_EQ(table.at(p, s), model.rest_length[s]);
  }
  // Played by the controller for several cycles: those springs never move; the others do.
  MotorController controller(model, program, table, kPaperTimeStep);
  SimState state = MakeRestState(model);
  bool others_moved = false;
  for (long long k = 0; k < StepAtTime(2.5 * program.cycle_period, kPaperTimeStep); ++k) {
    controller.Update(k, state.rest_length.data());
    for (int s : locked) ASSERT_EQ(state.rest_length[s], model.rest_length[s]) << "step " << k;
    for (int s : model.motor_springs) others_moved |= state.rest_length[s] != model.rest_length[s];
  }
  EXPECT_TRUE(others_moved);
}

// A short leg: every spring reaching the foot is scaled, in the model (the rest pose is not
// moved, so at t = 0 those springs are compressed and pull the foot in) and in the tables.
TEST(Damage, ShortScalesTheFootsSpringsInTheModelAndTheTables) {
  const CreatureModel intact = test::DefaultCreature();
  const CreatureModel model = Damaged("right_rear:short=0.8");
  const MotorProgram program = LoadMotorProgramOrDefault("", intact);
  const RestLengthTable before = GeometricRestLengths(intact, program);
  const RestLengthTable after = GeometricRestLengths(model, program);
  const int foot = intact.legs[intact.LegIndex("right_rear")].foot;
  int scaled = 0;
  for (int s = 0; s < intact.num_springs(); ++s) {
    const bool hit = intact.spring_a[s] == foot || intact.spring_b[s] == foot;
    scaled += hit;
    EXPECT_EQ(model.rest_length[s], hit ? intact.rest_length[s] * 0.8 : intact.rest_length[s]);
    for (int p = 0; p < before.num_positions; ++p) {
      EXPECT_EQ(after.at(p, s), hit ? before.at(p, s) * 0.8 : before.at(p, s)) << s;
    }
  }
  EXPECT_GE(scaled, 3);
  EXPECT_EQ(model.rest_position, intact.rest_position);
}

// A lost leg: every spring that reaches its foot is cut (no stiffness, no damping), nothing else
// changes, and its loose foot is never counted as a foot on the ground.
TEST(Damage, LostCutsTheFootsSpringsAndItsContactsDoNotCount) {
  const CreatureModel intact = test::DefaultCreature();
  const CreatureModel model = Damaged("right_middle:lost");
  const int leg = intact.LegIndex("right_middle");
  const int foot = intact.legs[leg].foot;
  int cut = 0;
  for (int s = 0; s < intact.num_springs(); ++s) {
    const bool reaches = intact.spring_a[s] == foot || intact.spring_b[s] == foot;
    cut += reaches;
    EXPECT_EQ(model.stiffness[s], reaches ? 0.0 : intact.stiffness[s]) << s;
    EXPECT_EQ(model.damping[s], reaches ? 0.0 : intact.damping[s]) << s;
    EXPECT_EQ(model.rest_length[s], intact.rest_length[s]);
  }
  EXPECT_GE(cut, 3);
  EXPECT_EQ(model.lost_legs, 1u << leg);
  EXPECT_EQ(model.damage, "right_middle:lost");
  EXPECT_EQ(ErrorOf("right_middle:lost=0.5"),
            "--damage entry 'right_middle:lost=0.5': lost takes no factor");
  // At rest every foot is down; the lost one is not counted.
  const SimState rest = MakeRestState(model);
  EXPECT_EQ(FeetOnGround(intact, rest), (1u << intact.legs.size()) - 1);
  EXPECT_EQ(FeetOnGround(model, rest), ((1u << intact.legs.size()) - 1) & ~(1u << leg));
  // Over a run the loose foot lies on the ground, but its duty factor is 0.
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 100;
  const RunResult r =
      EvaluateGenome(model, program, Genome(MakeGenomeLayout(model, program, false)), options);
  EXPECT_FALSE(r.diverged);
  EXPECT_EQ(r.foot_down_checks[static_cast<size_t>(leg)], 0);
  EXPECT_GT(r.foot_down_checks[static_cast<size_t>(intact.LegIndex("left_middle"))], 0);
}

// The paper's run (the unoptimised program, 1000 time units): each kind of damage changes it.
TEST(Damage, EachKindChangesThePapersRun) {
  const CreatureModel intact = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", intact);
  const Genome plain(MakeGenomeLayout(intact, program, false));
  RunOptions options;
  options.duration = 1000;
  const double base = EvaluateGenome(intact, program, plain, options).distance;
  for (const char* spec :
       {"right_front:weak=0.2", "left_rear:locked", "right_middle:short=0.8", "left_front:lost"}) {
    SCOPED_TRACE(spec);
    const RunResult r = EvaluateGenome(Damaged(spec), program, plain, options);
    EXPECT_FALSE(r.diverged);
    EXPECT_GT(std::abs(r.distance - base), 1e-3) << r.distance << " vs " << base;
  }
}

// The batched kernels (double on every instruction set, float lanes and the creature kernel)
// see the same damaged creature as the scalar path: the same bits as for an intact one.
TEST(Damage, BatchedPathsAgreeWithTheScalarPathOnADamagedCreature) {
  const CreatureModel model =
      Damaged("right_front:weak=0.2,left_rear:locked,right_middle:short=0.8,left_front:lost");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  RunOptions options;
  options.duration = 60;
  std::vector<Genome> genomes;
  genomes.emplace_back(MakeGenomeLayout(model, program, false));
  for (uint64_t k = 0; k < 5; ++k) genomes.push_back(test::RandomGenome(model, program, 300 + k));
  std::vector<const Genome*> pointers;
  for (const Genome& g : genomes) pointers.push_back(&g);
  std::vector<RunResult> scalar;
  for (const Genome& g : genomes) scalar.push_back(EvaluateGenome(model, program, g, options));
  for (BatchIsa isa : test::SupportedIsas()) {
    SCOPED_TRACE(BatchIsaName(isa));
    const std::vector<RunResult> batched =
        EvaluateGenomesBatched(model, program, pointers, options, 8, isa);
    for (size_t i = 0; i < genomes.size(); ++i) test::ExpectSameResult(scalar[i], batched[i], "");
  }
  // Float lanes: the same bits whatever the lane count and instruction set, as for an intact
  // creature (tests/unit/batch_test.cc).
  for (BatchIsa isa : test::SupportedIsas()) {
    SCOPED_TRACE(BatchIsaName(isa) + " float");
    const std::vector<RunResult> eight =
        EvaluateGenomesBatched(model, program, pointers, options, 8, isa, Precision::kFloat);
    for (size_t i = 0; i < genomes.size(); ++i) {
      const RunResult alone = EvaluateGenomesBatched(model, program, {pointers[i]}, options, 1,
                                                     BatchIsa::kGeneric, Precision::kFloat)
                                  .front();
      test::ExpectSameResult(alone, eight[i], "");
    }
  }
  if (BatchIsaSupported(BatchIsa::kAvx512)) {
    const std::vector<RunResult> kernel =
        EvaluateGenomesWithCreatureKernel(model, program, pointers, options);
    const std::vector<RunResult> lanes = EvaluateGenomesBatched(
        model, program, pointers, options, 16, BatchIsa::kAvx512, Precision::kFloat);
    for (size_t i = 0; i < genomes.size(); ++i) test::ExpectSameResult(lanes[i], kernel[i], "");
  }
}

// A resumed run must be refused if its damage differs: the scene fingerprint covers it, and an
// intact creature's fingerprint is what it was before damage existed.
TEST(Damage, TheSceneFingerprintTellsDamagesApart) {
  const CreatureModel intact = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", intact);
  const uint64_t base = SceneFingerprint(intact, program);
  EXPECT_EQ(SceneFingerprint(Damaged(""), program), base);
  std::vector<uint64_t> seen = {base};
  for (const char* spec : {"left_rear:locked", "right_rear:locked", "left_rear:weak=0.5",
                           "left_rear:short=0.9", "left_rear:locked,left_rear:weak=0.5"}) {
    const uint64_t f = SceneFingerprint(Damaged(spec), program);
    EXPECT_EQ(std::find(seen.begin(), seen.end(), f), seen.end()) << spec;
    seen.push_back(f);
  }
}

// A checkpoint records the damage beside the creature, for the reader and for resuming without
// --damage; the fingerprint refuses the checkpoint on a creature with another damage.
TEST(Damage, ACheckpointRecordsItAndRefusesAnotherDamage) {
  const CreatureModel model = Damaged("left_rear:locked");
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  EvolutionParams params;
  params.population = 2;
  params.generations = 1;
  EvolutionCheckpoint c;
  c.params = params;
  const std::string text =
      FormatCheckpoint(c, SceneFingerprint(model, program), "hexapod", model.damage);
  EXPECT_EQ(CheckpointDamage(text), "left_rear:locked");
  EXPECT_EQ(CheckpointDamage(FormatCheckpoint(c, SceneFingerprint(model, program), "hexapod")), "");
  try {
    ParseCheckpoint(text, "ck.json", Damaged("left_rear:weak=0.5"), program);
    FAIL() << "a checkpoint of another damage was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--damage"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hexgait
