// Small helpers shared by the tests: the default scene, and tiny hand-built models.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "ga/rng.h"
#include "model/creature.h"
#include "motor/assets.h"
#include "motor/motor_program.h"
#include "simd/isa.h"

namespace hexgait::test {

inline CreatureModel DefaultCreature() {
  return LoadCreatureOrDefault("");
}

// The batched kernels' instruction sets this CPU runs.
inline std::vector<BatchIsa> SupportedIsas() {
  std::vector<BatchIsa> isas;
  for (BatchIsa isa : {BatchIsa::kGeneric, BatchIsa::kAvx2, BatchIsa::kAvx512}) {
    if (BatchIsaSupported(isa)) isas.push_back(isa);
  }
  return isas;
}

// Every gene uniform in [-8, 7], from stream `stream` of `seed`: most such creatures fall, each
// at its own time.
inline Genome RandomGenome(const CreatureModel& model, const MotorProgram& program, uint64_t stream,
                           uint64_t seed = 12345) {
  Genome g(MakeGenomeLayout(model, program, false));
  Rng rng = Rng::ForStream(seed, stream);
  for (int i = 0; i < g.num_genes(); ++i) g.set_gene(i, static_cast<int>(rng.NextBelow(16)) - 8);
  return g;
}

// Particles and springs only (no legs, no derived fields): enough for forces and integrators.
inline CreatureModel TinyModel(const std::vector<Eigen::Vector3d>& positions,
                               const std::vector<double>& masses,
                               const std::vector<std::pair<int, int>>& springs, double stiffness,
                               double damping, double gravity) {
  CreatureModel m;
  m.rest_position = positions;
  m.mass = masses;
  for (double mass : masses) m.inv_mass.push_back(1.0 / mass);
  for (size_t i = 0; i < positions.size(); ++i) {
    std::string name = "p";
    name += std::to_string(i);
    m.particle_names.push_back(name);
  }
  for (const auto& [a, b] : springs) {
    m.spring_names.push_back("s");
    m.spring_a.push_back(a);
    m.spring_b.push_back(b);
    m.stiffness.push_back(stiffness);
    m.damping.push_back(damping);
    m.rest_length.push_back((positions[a] - positions[b]).norm());
    m.spring_leg.push_back(-1);
    m.spring_motor.push_back(0);
  }
  m.physics.gravity = gravity;
  return m;
}

}  // namespace hexgait::test
