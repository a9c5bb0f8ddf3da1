// Text helpers of the configuration tests (test_config.cpp, test_profile.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace softpack::config_test {

/// `text` with the first `from` replaced by `to` (a test failure when there is none).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Random draws of the range tests: a fixed seed, printed, so that a failure reproduces.
inline constexpr std::uint64_t kRangeTestSeed = 20240611;

// A value in [10^lo, 10^hi), drawn uniformly in its exponent.
inline double random_magnitude(std::mt19937_64& rng, double lo, double hi) {
  return std::pow(10.0, std::uniform_real_distribution<double>(lo, hi)(rng));
}

}  // namespace softpack::config_test

#define EXPECT_CONTAINS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)
