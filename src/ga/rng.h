// A small, portable random-number generator. std::mt19937 is portable but the standard
// distributions are not (their algorithms are implementation-defined), so the GA draws its
// numbers from here: the same seed gives the same run on every compiler and library.
#pragma once

#include <cmath>
#include <cstdint>

namespace hexgait {

// SplitMix64 (Steele, Lea, Flood 2014): 64-bit state, passes BigCrush, trivially seedable.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  // An independent stream for (seed, stream), e.g. one per generation.
  static Rng ForStream(uint64_t seed, uint64_t stream) {
    Rng mixer(seed ^ (0x9E3779B97F4A7C15ULL * (stream + 1)));
    return Rng(mixer.NextU64());
  }

  uint64_t NextU64() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1) with 53 random bits.
  double NextDouble() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }
  // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; bias below 2^-32 for small n).
  uint32_t NextBelow(uint32_t n) {
    return static_cast<uint32_t>(((NextU64() >> 32) * static_cast<uint64_t>(n)) >> 32);
  }
  bool Bernoulli(double p) { return NextDouble() < p; }
  // A standard normal number (Box-Muller; the second value of each pair is not kept, so a draw
  // never depends on an earlier one's parity).
  double Normal() {
    const double u1 = 1.0 - NextDouble();  // in (0, 1]
    const double u2 = NextDouble();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

 private:
  uint64_t state_;
};

}  // namespace hexgait
