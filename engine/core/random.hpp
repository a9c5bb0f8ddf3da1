// Deterministic random numbers: the same seed gives the same variates on every compiler and
// platform. std::*_distribution are implementation-defined, so variates are derived from the
// generator's raw bits here.
#pragma once
#include <cstdint>

#include "core/types.hpp"

namespace softpack {

/// xoshiro256** (Blackman & Vigna), seeded through SplitMix64.
class Random {
 public:
  explicit Random(std::uint64_t seed);
  std::uint64_t bits();
  /// Uniform in [0, 1): the top 53 bits of a draw.
  double uniform() { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform in the cube [-half, half)^3.
  Vec3 in_box(double half) { return {uniform(-half, half), uniform(-half, half), uniform(-half, half)}; }
  /// Uniform in the ball of radius R (rejection from the cube; about 1.9 draws of 3 numbers).
  Vec3 in_ball(double R);

 private:
  std::uint64_t s_[4];
};

}  // namespace softpack
