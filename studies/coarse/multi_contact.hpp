// The multi-contact probe (docs/coarse-grain.md, "Why"): one soft-particle resolved — a packing
// of the medium's generator in its shell, the shell held — pressed by k plane walls at once,
// each moved towards the centre by Δn Rs (k = 1: the soft-solid measurement itself; 2: two
// opposite walls; 6: the six faces of a cube), with the laws' own approach speed and relaxation
// (the profile's normal.speed and relaxation). The force on the first wall against Δn says
// whether a soft-particle answers each contact as if it were alone (the pairwise laws of the
// law file), or stiffer, its packing being compressed by all of them.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "coarse/settings.hpp"

namespace softpack {

struct MultiContactPoint {
  int walls = 1;
  double delta_n = 0.0;
  double Fn = 0.0;  ///< on the first wall (+z), after the relaxation [N]
};

/// For each k of `walls` (1, 2 or 6) and each Δn of `delta_n` (increasing, from contact).
std::vector<MultiContactPoint> measure_multi_contact(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                                     const std::vector<int>& walls, const std::vector<double>& delta_n,
                                                     const std::function<void(const MultiContactPoint&)>& progress = {});

}  // namespace softpack
