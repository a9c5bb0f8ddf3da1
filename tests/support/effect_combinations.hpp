// The combinations of effects the force loops are compiled for (contact/effects.hpp), as a
// GoogleTest parameter: an index into kEffectCombinations; effects_name() names each case.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "contact/effects.hpp"

namespace softpack::testing {

inline auto effect_combinations() { return ::testing::Range<std::size_t>(0, kEffectCombinations.size()); }

inline Effects effects_of(std::size_t index) { return kEffectCombinations[index]; }

inline std::string effects_name(const ::testing::TestParamInfo<std::size_t>& info) {
  const Effects fx = effects_of(info.param);
  std::string name = fx.friction ? "friction" : "frictionless";
  if (fx.damping) name += "_damped";
  if (fx.rotation) name += "_rotation";
  if (fx.synchronized) name += "_synchronized";
  return name;
}

}  // namespace softpack::testing
