// A walk over the closed contacts of a world, in list order (pairs, then each plane, then each
// shell), with what the normal law says of each: the residuals (sim/residuals.hpp), the watchdog
// and force_between read the contacts through it, so they see the law the force loops run.
#pragma once
#include <cmath>

#include "contact/tsuji_tangential.hpp"
#include "forces/force_field.hpp"

namespace softpack {

struct ClosedContact {
  enum class Kind { pair, plane, shell } kind = Kind::pair;
  int i = -1, j = -1;  ///< the spheres (j = -1 against a wall)
  int wall = -1;       ///< the plane or shell (kind plane, shell)
  double h = 0.0;      ///< overlap [m]
  double kn = 0.0, kt0 = 0.0;
  const Vec3* spring = nullptr;  ///< the tangential spring (null without friction)

  /// The normal law's force [N] and elastic energy [J].
  double Fn(const NormalLaw& law) const { return law.force(kn, h); }
  double normal_energy(const NormalLaw& law) const { return law.energy(kn, h); }
  /// The spring's elastic energy, 1/2 kt |xi|^2 [J] (0 without friction).
  double spring_energy() const { return spring ? tsuji::energy(kt0 * std::sqrt(h), v3(*spring)) : 0.0; }
};

/// Calls f(const ClosedContact&) for every contact with h > 0.
template <class F>
void for_each_closed_contact(const World& world, const ContactLists& lists, bool friction, F&& f) {
  const Particles& p = world.p;
  const PairList& pairs = lists.pairs;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int i = pairs.i[k], j = pairs.j[k];
    const double h = pairs.r_sum[k] - (p.x[i] - p.x[j]).norm();
    if (!(h > 0.0)) continue;
    f(ClosedContact{ClosedContact::Kind::pair, i, j, -1, h, pairs.k.kn[k], pairs.k.kt0[k], friction ? &pairs.spring[k] : nullptr});
  }
  const auto walls = [&](const auto& shapes, const std::vector<WallList>& wall_lists, ClosedContact::Kind kind) {
    for (std::size_t w = 0; w < shapes.size(); ++w) {
      const WallList& l = wall_lists[w];
      for (std::size_t k = 0; k < l.size(); ++k) {
        const int i = l.i[k];
        const double h = shapes[w].overlap(p.x[i], p.r[i]);
        if (!(h > 0.0)) continue;
        f(ClosedContact{kind, i, -1, static_cast<int>(w), h, l.k.kn[k], l.k.kt0[k], friction ? &l.spring[k] : nullptr});
      }
    }
  };
  walls(world.planes, lists.planes, ClosedContact::Kind::plane);
  walls(world.shells, lists.shells, ClosedContact::Kind::shell);
}

}  // namespace softpack
