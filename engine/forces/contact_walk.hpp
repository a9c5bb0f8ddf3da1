// A walk over the closed contacts of a world, in list order (pairs, then each plane, then each
// shell, then the soft-particles' pairs and planes), with what the normal law (the soft-particle
// law, for theirs) says of each: the residuals (sim/residuals.hpp), the watchdog
// and force_between read the contacts through it, so they see the law the force loops run.
#pragma once
#include <cmath>
#include <utility>

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
  const SoftContactConstants* soft = nullptr;  ///< a soft-particle's contact: its law's constants
  double body1 = 0.0, body2 = 0.0;  ///< the bodies' states at the last force evaluation (a law with one)

  /// The normal law's force [N] and elastic energy [J].
  double Fn(const NormalLaw& law) const { return soft ? soft_Fn(*soft, h) : law.force(kn, h, body1, body2); }
  double normal_energy(const NormalLaw& law) const {
    return soft ? soft_contact_energy(*soft, h, nullptr) : law.energy(kn, h, body1, body2);
  }
  /// The tangential stiffness kt [N/m] (Eq. 5; Eq. 8 for a soft-particle).
  double kt() const { return soft ? soft_kt(*soft, h) : kt0 * std::sqrt(h); }
  /// The spring's elastic energy, 1/2 kt |xi|^2 [J] (0 without friction).
  double spring_energy() const { return spring ? tsuji::energy(kt(), v3(*spring)) : 0.0; }
};

/// Calls f(const ClosedContact&) for every contact with h > 0.
template <class F>
void for_each_closed_contact(const World& world, const ContactLists& lists, bool friction, F&& f) {
  const Particles& p = world.p;
  const PairList& pairs = lists.pairs;
  const auto body = [&](int i) { return lists.body_state.empty() ? 0.0 : lists.body_state[static_cast<std::size_t>(i)]; };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int i = pairs.i[k], j = pairs.j[k];
    const double h = pairs.r_sum[k] - (p.x[i] - p.x[j]).norm();
    if (!(h > 0.0)) continue;
    ClosedContact c{ClosedContact::Kind::pair, i, j, -1, h, pairs.k.kn[k], pairs.k.kt0[k], friction ? &pairs.spring[k] : nullptr};
    c.body1 = body(i), c.body2 = body(j);
    f(std::as_const(c));
  }
  const auto walls = [&](const auto& shapes, const std::vector<WallList>& wall_lists, ClosedContact::Kind kind) {
    for (std::size_t w = 0; w < shapes.size(); ++w) {
      const WallList& l = wall_lists[w];
      for (std::size_t k = 0; k < l.size(); ++k) {
        const int i = l.i[k];
        const double h = shapes[w].overlap(p.x[i], p.r[i]);
        if (!(h > 0.0)) continue;
        ClosedContact c{kind, i, -1, static_cast<int>(w), h, l.k.kn[k], l.k.kt0[k], friction ? &l.spring[k] : nullptr};
        c.body1 = body(i);
        f(std::as_const(c));
      }
    }
  };
  walls(world.planes, lists.planes, ClosedContact::Kind::plane);
  walls(world.shells, lists.shells, ClosedContact::Kind::shell);
  if (!lists.soft) return;
  const SoftLists& soft = *lists.soft;
  for (std::size_t k = 0; k < soft.pairs.size(); ++k) {
    const int i = soft.pairs.i[k], j = soft.pairs.j[k];
    const double h = soft.pairs.r_sum[k] - (p.x[i] - p.x[j]).norm();
    if (!(h > 0.0)) continue;
    ClosedContact c{ClosedContact::Kind::pair, i, j, -1, h, 0.0, 0.0, friction ? &soft.pairs.spring[k] : nullptr};
    c.soft = &soft.pair_k[k];
    f(std::as_const(c));
  }
  for (std::size_t w = 0; w < world.planes.size(); ++w) {
    const WallList& l = soft.planes[w];
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int i = l.i[k];
      const double h = world.planes[w].overlap(p.x[i], p.r[i]);
      if (!(h > 0.0)) continue;
      ClosedContact c{ClosedContact::Kind::plane, i, -1, static_cast<int>(w), h, 0.0, 0.0, friction ? &l.spring[k] : nullptr};
      c.soft = &soft.plane_k[w][k];
      f(std::as_const(c));
    }
  }
}

}  // namespace softpack
