// The combinations of effects the force loops are compiled for, as a GoogleTest parameter:
// bits friction (8), damping (4), rotation (2), synchronized history update (1); rotation and the
// history frame need friction. effects_name() names each case in the test list.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "sim/pair_forces.hpp"

namespace softpack::testing {

inline auto effect_combinations() { return ::testing::Values(0, 4, 8, 9, 10, 11, 12, 13, 14, 15); }

inline PairForceEffects effects_of(int bits) {
  return PairForceEffects{(bits & 8) != 0, (bits & 4) != 0, (bits & 2) != 0, (bits & 1) != 0};
}

inline std::string effects_name(const ::testing::TestParamInfo<int>& info) {
  const int b = info.param;
  std::string name = (b & 8) ? "friction" : "frictionless";
  if (b & 4) name += "_damped";
  if (b & 2) name += "_rotation";
  if (b & 1) name += "_synchronized";
  return name;
}

}  // namespace softpack::testing
