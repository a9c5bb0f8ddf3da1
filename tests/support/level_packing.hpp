// A soft-particle's packing parameters for the nested tests (packing/nested.hpp): Rs 16 mm,
// r_max 0.3 Rs, Π = √10 per level (two levels span the decade of the project's soft-particle),
// b = 3.5, β = 1 and `trials` attempts (cheap packings).
#pragma once
#include <cmath>

#include "packing/generator.hpp"

namespace softpack::testing {

inline PackingParameters level_packing(long trials = 1000) {
  PackingParameters p;
  p.Rs = 0.016;
  p.r_max = 0.3 * p.Rs;
  p.polydispersity = std::sqrt(10.0);
  p.exponent = 3.5;
  p.beta = 1.0;
  p.trials = trials;
  p.shell_is_neighbour = true;
  p.level_ratio = 2.0;
  return p;
}

}  // namespace softpack::testing
