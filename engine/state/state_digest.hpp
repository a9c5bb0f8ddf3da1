// A digest of a state's bits (x, v, w, F, T and the springs): equal digests mean a change left
// every result bit alone (softpack-bench-scene --digest, tests/physics/test_result_bits.cpp).
#pragma once
#include <cstdint>

#include "core/fnv1a.hpp"
#include "state/simulation_state.hpp"

namespace softpack {

inline void add_bits(Fnv1a& h, const SimulationState& s) {
  for (const auto* a : {&s.x, &s.v, &s.w, &s.F, &s.T}) h.add(a->data(), a->size() * sizeof(Vec3));
  for (const auto& sp : s.pair_springs) h.add(&sp.i, sizeof sp.i), h.add(&sp.j, sizeof sp.j), h.add(&sp.xi, sizeof sp.xi);
  for (const auto* lists : {&s.plane_springs, &s.shell_springs})
    for (const auto& l : *lists)
      for (const auto& sp : l) h.add(&sp.i, sizeof sp.i), h.add(&sp.xi, sizeof sp.xi);
  // Free shells' centres and motion: nothing to add in a scene without them, whose digest is
  // unchanged.
  if (!s.shell_velocities.empty())
    for (const auto* a : {&s.shell_centres, &s.shell_velocities, &s.shell_spins, &s.shell_forces, &s.shell_torques})
      h.add(a->data(), a->size() * sizeof(Vec3));
}

inline std::uint64_t state_digest(const SimulationState& s) {
  Fnv1a h;
  add_bits(h, s);
  return h.value;
}

}  // namespace softpack
