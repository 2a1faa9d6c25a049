// The creature kernel: explicit Euler in float for a few creatures, each held whole in AVX-512
// registers (a creature's 14 particles across the 16 lanes of one register per quantity, its
// springs across three). Where the lanes kernel (sim/batch_kernel.h) needs 8 or more creatures
// to fill its vectors, this one fills them with one creature, which makes the small batches of
// the paper's population (3-4 creatures per generation) fast.
//
// Each creature gets exactly the float lanes' result: the same operations on the same values in
// the same order, spring forces summed onto each particle in spring order (docs/model.md,
// "Creature kernel"). Plain structs only: the AVX-512 translation unit includes this header.
#pragma once

namespace hexgait {

// Particles and springs one creature may have for this kernel.
inline constexpr int kCreatureKernelParticles = 16;
inline constexpr int kCreatureKernelSprings = 48;

// One creature's particles: quantity q of particle i at q[i]; lanes past the model's particles
// hold a still particle above the ground.
struct alignas(64) CreatureRegisters {
  float x[16], y[16], z[16], vx[16], vy[16], vz[16];
};

// The model, rounded to float and laid out for the kernel. Spring s is at group s / 16, lane
// s % 16; padding springs join particles 0 and 1 with zero stiffness and damping.
struct alignas(64) CreatureKernelModel {
  int num_springs = 0;
  int num_groups = 0;  // ceil(num_springs / 16)
  int num_ranks = 0;   // the most springs any particle has
  alignas(64) int spring_a[3][16];
  alignas(64) int spring_b[3][16];
  alignas(64) float stiffness[3][16];
  alignas(64) float damping[3][16];
  alignas(64) float weight[16];  // -mass * gravity, as float
  alignas(64) float h[16];       // dt * inverse mass, as float
  // Rank r: particle i's r-th spring (in spring order) is rank_spring[r][i]; it adds that
  // spring's force when bit i of rank_add[r] is set, subtracts it when bit i of rank_sub[r] is.
  alignas(64) int rank_spring[kCreatureKernelSprings][16];
  unsigned short rank_add[kCreatureKernelSprings], rank_sub[kCreatureKernelSprings];
  float dt = 0, ground_stiffness = 0, ground_damping = 0, friction = 0, slip_velocity2 = 0;
};

// One creature's spring rest lengths, padded to the kernel's three groups of 16.
struct alignas(64) CreatureRestLengths {
  float length[kCreatureKernelSprings];
};

// One explicit Euler step of `count` creatures; creature c has rest_length[c].
// Defined in creature_kernel_avx512.cc; call only where BatchIsaSupported(kAvx512).
void StepCreaturesAvx512(const CreatureKernelModel& model, CreatureRegisters* creatures,
                         const CreatureRestLengths* rest_length, int count);

}  // namespace hexgait
