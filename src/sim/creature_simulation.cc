#include "sim/creature_simulation.h"

#include <algorithm>

#include "motor/leg_targets.h"
#include "sim/batch_kernel.h"
#include "util/error.h"

namespace hexgait {

namespace {

// The model in the kernel's layout, every constant rounded to float as BatchStateT<float> and
// MakeBatchKernelArgs round it.
void FillKernelModel(const CreatureModel& model, double dt, CreatureKernelModel& k) {
  const int n = model.num_particles();
  const int ns = model.num_springs();
  const auto f = [](double v) { return static_cast<float>(v); };
  k.num_springs = ns;
  k.num_groups = (ns + 15) / 16;
  for (int s = 0; s < 48; ++s) {
    const bool real = s < ns;
    k.spring_a[s / 16][s % 16] = real ? model.spring_a[s] : 0;
    k.spring_b[s / 16][s % 16] = real ? model.spring_b[s] : 1;
    k.stiffness[s / 16][s % 16] = real ? f(model.stiffness[s]) : 0.0f;
    k.damping[s / 16][s % 16] = real ? f(model.damping[s]) : 0.0f;
  }
  const PhysicsConstants& phys = model.physics;
  const float g = f(phys.gravity);
  k.dt = f(dt);
  for (int i = 0; i < 16; ++i) {
    k.weight[i] = i < n ? -f(model.mass[i]) * g : 0.0f;
    k.h[i] = i < n ? k.dt * f(model.inv_mass[i]) : 0.0f;
  }
  std::vector<std::vector<int>> incident(n);  // 2 * spring + (1 at its b end), spring order
  for (int s = 0; s < ns; ++s) {
    incident[model.spring_a[s]].push_back(2 * s);
    incident[model.spring_b[s]].push_back(2 * s + 1);
  }
  k.num_ranks = 0;
  for (const auto& list : incident) k.num_ranks = std::max(k.num_ranks, int(list.size()));
  for (int r = 0; r < k.num_ranks; ++r) {
    unsigned add = 0, sub = 0;
    for (int i = 0; i < 16; ++i) {
      const bool has = i < n && r < static_cast<int>(incident[i].size());
      k.rank_spring[r][i] = has ? incident[i][r] >> 1 : 0;
      if (has) ((incident[i][r] & 1) ? sub : add) |= 1u << i;
    }
    k.rank_add[r] = static_cast<unsigned short>(add);
    k.rank_sub[r] = static_cast<unsigned short>(sub);
  }
  k.ground_stiffness = f(phys.ground_stiffness);
  k.ground_damping = f(phys.ground_damping);
  k.friction = f(phys.friction);
  k.slip_velocity2 = f(phys.slip_velocity * phys.slip_velocity);
}

std::vector<RestLengthTable> Tables(std::span<const RestLengthTable> tables) {
  if (tables.empty()) throw InputError("a batch needs at least one rest-length table");
  return {tables.begin(), tables.end()};
}

}  // namespace

bool CreatureSimulation::Available(const CreatureModel& model) {
  // BestBatchIsa: AVX-512 is supported and not capped by HEXGAIT_BATCH_ISA (valgrind).
  return BestBatchIsa() == BatchIsa::kAvx512 && model.num_particles() <= kCreatureKernelParticles &&
         model.num_springs() <= kCreatureKernelSprings;
}

CreatureSimulation::CreatureSimulation(const CreatureModel& model, const MotorProgram& program,
                                       std::span<const RestLengthTable> tables, double dt)
    : dt_(dt),
      controller_(model, program, Tables(tables), dt, sizeof(CreatureRestLengths) / sizeof(float)) {
  if (!Available(model)) throw InputError("the creature kernel is not available for this model");
  const int count = static_cast<int>(tables.size());
  const SimState start = MakeRestState(model);
  CreatureRestLengths rest{};
  for (int s = 0; s < model.num_springs(); ++s) {
    rest.length[s] = static_cast<float>(start.rest_length[s]);
  }
  rest_length_.assign(count, rest);
  CreatureRegisters r{};
  for (int i = 0; i < 16; ++i) {
    const bool real = i < model.num_particles();
    // Padding particles: still, above the ground, weightless; no spring reaches them.
    r.x[i] = real ? static_cast<float>(start.x[i]) : 0.0f;
    r.y[i] = real ? static_cast<float>(start.y[i]) : 0.0f;
    r.z[i] = real ? static_cast<float>(start.z[i]) : 1.0f;
    r.vx[i] = real ? static_cast<float>(start.vx[i]) : 0.0f;
    r.vy[i] = real ? static_cast<float>(start.vy[i]) : 0.0f;
    r.vz[i] = real ? static_cast<float>(start.vz[i]) : 0.0f;
  }
  creatures_.assign(count, r);
  FillKernelModel(model, dt, kernel_model_);
  step_ = start.step;
  time_ = start.time;
}

void CreatureSimulation::Extract(int c, SimState& out) const {
  const CreatureRegisters& r = creatures_[c];
  for (int i = 0; i < out.num_particles(); ++i) {
    out.x[i] = r.x[i];
    out.y[i] = r.y[i];
    out.z[i] = r.z[i];
    out.vx[i] = r.vx[i];
    out.vy[i] = r.vy[i];
    out.vz[i] = r.vz[i];
  }
  for (size_t s = 0; s < out.rest_length.size(); ++s)
    out.rest_length[s] = rest_length_[c].length[s];
  out.step = step_;
  out.time = time_;
}

}  // namespace hexgait
