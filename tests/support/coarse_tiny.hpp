// The coarse-grain study's tiny settings (tests/data/coarse-grain-tiny.yaml), read once: the
// medium, compression and multi-contact tests' small soft-particles; and at two levels.
#pragma once
#include <string>

#include "coarse/settings.hpp"

namespace softpack::testing {

inline const CoarseGrainSettings& coarse_grain_tiny() {
  static const CoarseGrainSettings s =
      read_coarse_grain_settings(std::string(SOFTPACK_SOURCE_DIR) + "/tests/data/coarse-grain-tiny.yaml", SOFTPACK_SOURCE_DIR);
  return s;
}

/// The same settings with the sites at two levels (nested soft-particles, docs/nested.md): every
/// content made.
inline const CoarseGrainSettings& coarse_grain_nested_tiny() {
  static const CoarseGrainSettings s = [] {
    CoarseGrainSettings n = coarse_grain_tiny();
    n.levels = 2;
    return n;
  }();
  return s;
}

}  // namespace softpack::testing
