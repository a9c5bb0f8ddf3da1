// Deterministic random numbers: the same seed gives the same variates on every compiler and
// platform. std::*_distribution are implementation-defined, so variates are derived from the
// generator's raw bits here.
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "core/types.hpp"

namespace softpack {

/// The seeds of the project: the integers 0 <= seed <= kMaxSeed = 2^63 - 1. Random takes any
/// 64-bit value, but every file stores its seed as a signed 64-bit integer (HDF5 int64,
/// formats/h5_fields.hpp), and a seed names files (seed-<seed>.h5, workflow/packing.mk): a seed
/// beyond the range would be recorded as another one than the file's name says.
inline constexpr std::uint64_t kMaxSeed = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

/// The seed that `text` writes: decimal digits only, read exactly (core/integer_text.hpp; no
/// sign, point, exponent, space or leading zero), within 0..kMaxSeed. Otherwise std::nullopt,
/// and `error` says why ("'1.5' is not allowed; allowed: ...").
std::optional<std::uint64_t> parse_seed(std::string_view text, std::string& error);

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
