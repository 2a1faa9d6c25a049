#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "embedded_assets.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "motor/motor_program_io.h"
#include "test_util.h"
#include "util/error.h"

namespace hexgait {
namespace {

MotorProgram ProgramFromJson(const nlohmann::json& doc, const CreatureModel& model) {
  return ParseMotorProgram(doc.dump(), "program.json", model);
}

nlohmann::json DefaultProgramJson() {
  return nlohmann::json::parse(reinterpret_cast<const char*>(kEmbeddedMetachronalJson));
}

TEST(MotorProgram, HasThePapersShape) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram p = LoadMotorProgramOrDefault("", model);
  EXPECT_EQ(p.num_written_instructions(), 19);  // 18 triples plus the loop
  EXPECT_EQ(p.num_positions(), 6);
  EXPECT_EQ(p.expanded.size(), 36u);  // every leg visits all six positions each cycle
  std::vector<int> per_leg(model.legs.size(), 0);
  for (const Instruction& in : p.expanded) ++per_leg[in.leg];
  for (int count : per_leg) EXPECT_EQ(count, 6);
  // The cycle lasts about 1000/15 time units, as in the paper.
  EXPECT_NEAR(1000.0 / p.cycle_period, 15.0, 0.5);
}

TEST(MotorProgram, LeftLegsReplayTheRightHalfACycleLater) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram p = LoadMotorProgramOrDefault("", model);
  for (const Instruction& right : p.instructions) {
    const int left = model.legs[right.leg].mirror;
    const double expected = std::fmod(right.time + p.cycle_period / 2, p.cycle_period);
    bool found = false;
    for (const Instruction& in : p.expanded) {
      found = found || (in.leg == left && in.position == right.position &&
                        std::fabs(in.time - expected) < 1e-9);
    }
    EXPECT_TRUE(found) << model.legs[left].name << " at " << expected;
  }
}

TEST(MotorProgram, MetachronalWaveOrder) {
  // Each leg's swing starts after the previous leg in the wave: right rear, middle, front,
  // then left rear, middle, front.
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram p = LoadMotorProgramOrDefault("", model);
  const char* order[] = {"right_rear", "right_middle", "right_front",
                         "left_rear",  "left_middle",  "left_front"};
  double previous = -1;
  for (const char* name : order) {
    double swing = -1;
    for (const Instruction& in : p.expanded) {
      if (in.leg == model.LegIndex(name) && p.positions[in.position].name == "swing")
        swing = in.time;
    }
    // Times wrap around the cycle; unwrap so the wave is increasing.
    if (swing < previous) swing += p.cycle_period;
    EXPECT_GT(swing, previous) << name;
    previous = swing;
  }
}

TEST(LegTargets, NeutralPositionReproducesTheRestPose) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram p = LoadMotorProgramOrDefault("", model);
  const RestLengthTable table = GeometricRestLengths(model, p);
  for (int pos = 0; pos < p.num_positions(); ++pos) {
    if (!p.positions[pos].foot_offset.isZero()) continue;
    for (int s : model.motor_springs) {
      EXPECT_NEAR(table.at(pos, s), model.rest_length[s], 1e-12) << model.spring_names[s];
    }
  }
}

TEST(LegTargets, GeneShiftsOneSpringAtOnePosition) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram p = LoadMotorProgramOrDefault("", model);
  Genome genome(MakeGenomeLayout(model, p, false));
  genome.set_gene(7, -3);
  const RestLengthTable base = GeometricRestLengths(model, p);
  const RestLengthTable perturbed = PerturbedRestLengths(model, p, genome);
  const int spring = genome.layout().springs_of_gene[7][0];
  const int position = genome.layout().position_of_gene[7];
  for (int pos = 0; pos < p.num_positions(); ++pos) {
    for (int s = 0; s < model.num_springs(); ++s) {
      const double expected =
          base.at(pos, s) + ((pos == position && s == spring) ? -3 * p.gene_length_step : 0);
      EXPECT_DOUBLE_EQ(perturbed.at(pos, s), expected);
    }
  }
}

TEST(Controller, AppliesInstructionsAtTheirSteps) {
  const CreatureModel model = test::DefaultCreature();
  nlohmann::json doc = DefaultProgramJson();
  doc["transition_time"] = 0.0;  // jumps, so the step of each change is exact
  const MotorProgram p = ProgramFromJson(doc, model);
  const double dt = 0.0025;
  MotorController controller(model, p, GeometricRestLengths(model, p), dt);
  std::vector<double> rest = model.rest_length;
  const Instruction& second = p.expanded[6];  // first instruction after t = 0
  ASSERT_GT(second.time, 0.0);
  const long long step = std::llround(second.time / dt);
  const int spring = model.legs[second.leg].springs[0];
  controller.Update(0, rest.data());
  controller.Update(step - 1, rest.data());
  const double before = rest[spring];
  controller.Update(step, rest.data());
  EXPECT_DOUBLE_EQ(rest[spring], GeometricRestLengths(model, p).at(second.position, spring));
  EXPECT_NE(rest[spring], before);
  // One cycle later the same instruction fires again at the same phase.
  const long long cycle_steps = std::llround(p.cycle_period / dt);
  controller.Update(step + cycle_steps - 1, rest.data());
  rest[spring] = -1;  // sentinel: only a new application overwrites it
  controller.Update(step + cycle_steps, rest.data());
  EXPECT_DOUBLE_EQ(rest[spring], GeometricRestLengths(model, p).at(second.position, spring));
}

TEST(Controller, TransitionMovesRestLengthLinearly) {
  const CreatureModel model = test::DefaultCreature();
  nlohmann::json doc = DefaultProgramJson();
  doc["transition_time"] = 1.0;
  const MotorProgram p = ProgramFromJson(doc, model);
  const double dt = 0.0025;
  const RestLengthTable table = GeometricRestLengths(model, p);
  MotorController controller(model, p, table, dt);
  std::vector<double> rest = model.rest_length;
  const Instruction& first = p.expanded[0];
  const int spring = model.legs[first.leg].springs[0];
  const double from = rest[spring], to = table.at(first.position, spring);
  ASSERT_NE(from, to);
  controller.Update(0, rest.data());
  EXPECT_NEAR(rest[spring], from + (to - from) / 400.0, 1e-12);  // 1 of 400 steps
  for (long long k = 1; k <= 199; ++k) controller.Update(k, rest.data());
  EXPECT_NEAR(rest[spring], from + 0.5 * (to - from), 1e-12);
  for (long long k = 200; k <= 500; ++k) controller.Update(k, rest.data());
  EXPECT_DOUBLE_EQ(rest[spring], to);
}

void ExpectProgramError(const std::function<void(nlohmann::json&)>& edit,
                        const std::string& expected) {
  const CreatureModel model = test::DefaultCreature();
  nlohmann::json doc = DefaultProgramJson();
  edit(doc);
  try {
    ProgramFromJson(doc, model);
    FAIL() << "no error; expected '" << expected << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(MotorProgramJson, RejectsBadInput) {
  ExpectProgramError([](auto& d) { d["instructions"][0]["leg"] = "tail"; }, "no leg named 'tail'");
  ExpectProgramError([](auto& d) { d["instructions"][0]["position"] = "jump"; },
                     "no position named 'jump'");
  ExpectProgramError([](auto& d) { d["instructions"][0]["time"] = 66.0; },
                     "must be below cycle_period");
  ExpectProgramError([](auto& d) { d["instructions"][0]["leg"] = "left_rear"; },
                     "both have instructions");
  ExpectProgramError(
      [](auto& d) {
        auto& list = d["instructions"];
        for (auto it = list.begin(); it != list.end();) {
          it = (*it)["leg"] == "right_front" ? list.erase(it) : it + 1;
        }
      },
      "has no instructions");
  ExpectProgramError(
      [](auto& d) {
        d["positions"].push_back({{"name", "extra"}, {"foot_offset", {0, 0, 0}}});
      },
      "position 'extra' is never used");
  ExpectProgramError([](auto& d) { d["cycle_period"] = 0; }, "cycle_period: must be positive");
  ExpectProgramError(
      [](auto& d) {
        d["positions"][0]["foot_offset"] = {1, 2};
      },
      "expected [forward, outward, up]");
}

}  // namespace
}  // namespace hexgait
