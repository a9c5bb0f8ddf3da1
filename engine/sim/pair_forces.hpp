// Sphere-sphere contact forces for a whole Verlet list, vectorised over contacts.
//
// Same physics and the same arithmetic, operation for operation, as the per-contact routine
// of contact/contact_force.hpp (advance_spring, then contact_force), which stays the
// reference and serves the walls; tests/physics/test_pair_forces.cpp checks the two agree.
// The touching pairs are first picked out of the list, then processed in batches laid out
// as structure-of-arrays, so that the compiler evaluates several contacts per instruction.
// The batch loop is compiled for x86-64-v4 (AVX-512), v3 (AVX2) and the baseline, chosen at
// run time; without FMA contraction every variant gives the same bits.
#pragma once
#include <cstddef>
#include <vector>

#include "core/types.hpp"
#include "neighbor/contact_list.hpp"

namespace softpack {

/// The sphere arrays the pair forces read and accumulate into (w, r and T only with rotation).
struct PairForceArrays {
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;  ///< half-step velocities
  const Vec3* w = nullptr;
  const double* r = nullptr;
  Vec3* F = nullptr;
  Vec3* T = nullptr;
};

struct PairForceEffects {
  bool friction = false, damping = false, rotation = false, synchronized = false;
};

/// Adds the force (and torque) of every touching pair of `list` to the spheres, advances the
/// springs of touching pairs by `spring_dt` and clears those of open ones. `scratch` is
/// reused between calls.
void accumulate_pair_forces(PairList& list, const PairForceArrays& a, const PairForceEffects& fx, double spring_dt,
                            std::vector<int>& scratch);

}  // namespace softpack
