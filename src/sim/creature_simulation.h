// Float evaluations of a few creatures with the creature kernel (sim/creature_kernel.h): the
// same interface as BatchSimulation<float>, and for each creature the same bits as a float
// lane, but a creature fills the vector registers on its own, so a batch of 1-4 creatures runs
// several times faster than in lanes.
#pragma once

#include <span>
#include <vector>

#include "model/creature.h"
#include "motor/batch_controller.h"
#include "motor/motor_program.h"
#include "sim/batch_state.h"
#include "sim/creature_kernel.h"
#include "sim/state.h"

namespace hexgait {

class CreatureSimulation {
 public:
  // Whether this CPU has the kernel's instruction set (AVX-512) and `model` fits it (at most
  // kCreatureKernelParticles particles and kCreatureKernelSprings springs).
  static bool Available(const CreatureModel& model);

  // One creature per rest-length table (ga/genome.h decodes genomes into them). Requires
  // Available(model).
  CreatureSimulation(const CreatureModel& model, const MotorProgram& program,
                     std::span<const RestLengthTable> tables, double dt);
  CreatureSimulation(const CreatureSimulation&) = delete;
  CreatureSimulation& operator=(const CreatureSimulation&) = delete;

  // `steps` explicit Euler steps of every creature. Does not allocate.
  void Advance(long long steps) {
    const int count = lanes();
    for (long long k = 0; k < steps; ++k) {
      controller_.Update(step_, rest_length_.front().length);
      StepCreaturesAvx512(kernel_model_, creatures_.data(), rest_length_.data(), count);
      ++step_;
    }
    time_ = static_cast<double>(step_) * dt_;
  }
  // Creature `c`'s state, widened to double; `out` must be sized for the model.
  void Extract(int c, SimState& out) const;

  int lanes() const { return controller_.lanes(); }
  long long step() const { return step_; }
  double time() const { return time_; }
  double cycle_period() const { return controller_.cycle_period(); }

 private:
  double dt_;
  // Writes each creature's rest lengths contiguously, for the kernel to load as whole vectors.
  BatchMotorController controller_;
  std::vector<CreatureRestLengths, CacheAlignedAllocator<CreatureRestLengths>> rest_length_;
  std::vector<CreatureRegisters, CacheAlignedAllocator<CreatureRegisters>> creatures_;
  CreatureKernelModel kernel_model_;
  long long step_ = 0;
  double time_ = 0;
};

}  // namespace hexgait
