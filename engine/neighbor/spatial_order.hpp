// The spheres in spatial order: sorted along a Z-order (Morton) curve through a grid of 2^10
// cells per side over their bounding box, so that spheres close in space are close in memory.
// The force loops gain twice: a sphere's contacts read nearby memory, and on threads
// (core/parallel.hpp) each thread's share of the spheres is a compact region whose contacts
// with other shares (evaluated twice, forces/pair_contacts.hpp) are few. LAMMPS sorts its atoms
// the same way (atom_modify sort, every 1000 steps); the benchmark's scene is ordered once.
#pragma once
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace softpack {

/// The order of the points along the curve: order[k] is the index of the k-th. Ties (points in
/// one cell) keep their order; the same points give the same order on any machine.
std::vector<std::int32_t> spatial_order(const std::vector<Vec3>& x);

}  // namespace softpack
