// The continuous-time rest lengths (what the reference uses) against the step-based controller.
#include "motor/rest_schedule.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "sim/state.h"
#include "test_util.h"

namespace hexgait {
namespace {

TEST(RestLengthSchedule, MatchesTheControllerAtStepEnds) {
  const CreatureModel model = test::DefaultCreature();
  const MotorProgram program = LoadMotorProgramOrDefault("", model);
  Genome genome(MakeGenomeLayout(model, program, false));
  for (int i = 0; i < genome.num_genes(); ++i) genome.set_gene(i, (i * 5) % 16 - 8);
  const RestLengthTable table = PerturbedRestLengths(model, program, genome);
  const double duration = 2.5 * program.cycle_period;
  const RestLengthSchedule schedule(model, program, table, model.rest_length, duration);
  for (double dt : {0.01, 0.0025}) {
    MotorController controller(model, program, table, dt);
    std::vector<double> stepped = model.rest_length, continuous(model.num_springs());
    double worst = 0, moved = 0;
    const long long steps = std::llround(duration / dt);
    for (long long k = 0; k + 1 < steps; ++k) {
      controller.Update(k, stepped.data());
      // Update(k) gives the lengths for the end of step k.
      schedule.At(static_cast<double>(k + 1) * dt, continuous.data());
      for (int s = 0; s < model.num_springs(); ++s) {
        worst = std::fmax(worst, std::fabs(stepped[s] - continuous[s]));
        moved = std::fmax(moved, std::fabs(stepped[s] - model.rest_length[s]));
      }
    }
    EXPECT_LT(worst, 1e-12) << "dt " << dt;
    EXPECT_GT(moved, 0.01);  // the motor really moved the legs
  }
  // Kinks at instruction times and transition ends only, sorted.
  EXPECT_FALSE(schedule.breakpoints().empty());
  EXPECT_TRUE(std::is_sorted(schedule.breakpoints().begin(), schedule.breakpoints().end()));
}

}  // namespace
}  // namespace hexgait
