// The contacts the pair style softpack/soft walks in each of its passes (pair/pair_soft_particle.cpp,
// pair/soft_body_passes.cpp): the listed pairs touching a soft-particle, and the local
// soft-particles touching a wall.
#pragma once
#include "pair/pair_soft_particle.hpp"
#include "pair/soft_wall.hpp"

namespace softpack::lammps {

template <class F>
inline void PairSoftParticle::each_contact(F&& fn) {
  double** x = atom->x;
  const double* radius = atom->radius;
  const int* type = atom->type;
  const LAMMPS_NS::tagint* tag = atom->tag;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* neighbours = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = neighbours[jj] & NEIGHMASK;
      if (soft_[static_cast<std::size_t>(type[i])] != 1 && soft_[static_cast<std::size_t>(type[j])] != 1) continue;
      // Body 1 the smaller tag: a pair on two ranks is the same arithmetic on both (its springs).
      const int a = tag[i] < tag[j] ? i : j, b = a == i ? j : i;
      const V3<double> d{x[a][0] - x[b][0], x[a][1] - x[b][1], x[a][2] - x[b][2]};
      const double r_sum = radius[a] + radius[b];
      if (dot(d, d) < r_sum * r_sum) fn(i, j, a, b, d, r_sum);
    }
  }
}

template <class F>
inline void PairSoftParticle::each_wall_contact(F&& fn) {
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const FixSoftWall& wall = *walls_[w];
    for (int i = 0; i < atom->nlocal; ++i) {
      if (soft_[static_cast<std::size_t>(atom->type[i])] != 1 || !(atom->mask[i] & wall.group_bit())) continue;
      const double h = wall.overlap(atom->x[i], atom->radius[i]);
      if (h > 0.0) fn(i, w, h);
    }
  }
}

}  // namespace softpack::lammps
