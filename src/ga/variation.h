// The GA's variation operators on a chromosome's bits, shared by the paper's GA
// (ga/evolution.h) and MAP-Elites (ga/map_elites.h) so that the two differ only in how they
// select and keep genomes, never in how they make children.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ga/rng.h"

namespace hexgait {

// Flips each bit with probability `rate` (one draw per bit, in order).
inline void MutateBits(std::vector<uint8_t>& bits, double rate, Rng& rng) {
  for (uint8_t& bit : bits) {
    if (rng.Bernoulli(rate)) bit ^= 1u;
  }
}

// One-point crossover: the bits from a cut in [1, size - 1] on come from `other`.
inline void CrossOver(std::vector<uint8_t>& bits, const std::vector<uint8_t>& other, Rng& rng) {
  const uint32_t cut = 1 + rng.NextBelow(static_cast<uint32_t>(bits.size() - 1));
  for (size_t i = cut; i < bits.size(); ++i) bits[i] = other[i];
}

}  // namespace hexgait
