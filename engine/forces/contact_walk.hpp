// A walk over the closed contacts of a world, in list order (family by family: pairs, then each
// plane, then each shell), with what the contact's model says of each: the residuals
// (sim/residuals.hpp), the watchdog, the active set and force_between read the contacts through
// it, so they see the law the force loops run.
#pragma once
#include <cmath>
#include <type_traits>
#include <utility>

#include "contact/tsuji_tangential.hpp"
#include "forces/contact_models.hpp"
#include "forces/force_field.hpp"

namespace softpack {

struct ClosedContact {
  enum class Kind { pair, plane, shell } kind = Kind::pair;
  int i = -1, j = -1;  ///< the spheres (j = -1 against a wall)
  int wall = -1;       ///< the plane or shell (kind plane, shell)
  double h = 0.0;      ///< overlap [m]
  const SceneModel* model = nullptr;  ///< the contact's model
  const ConstantArrays* constants = nullptr;
  std::size_t k = 0;                  ///< its position in its list (and in `constants`)
  const Vec3* spring = nullptr;       ///< the tangential spring (null without friction)
  double body1 = 0.0, body2 = 0.0;    ///< the bodies' states at the last force evaluation (a model with one)
  V3<double> n{};                     ///< the unit normal, from body 2 to body 1 (from j to i; a wall's towards the sphere)
  /// The bodies' stress tensors of the last force evaluation (a law with a stress term; a wall's: none).
  BodyStress stress1{}, stress2{};

  /// What the contact's law reads of it.
  ContactGeometry<double> geometry() const {
    ContactGeometry<double> g{};
    g.n = n, g.h = h, g.body1 = body1, g.body2 = body2, g.stress1 = stress1, g.stress2 = stress2;
    return g;
  }
  /// The normal law's force [N] and elastic energy [J] (without a stress term: it has no potential).
  double Fn() const { return model->Fn(*constants, k, geometry()); }
  double normal_energy() const { return model->normal_energy(*constants, k, geometry()); }
  /// The tangential stiffness kt [N/m] (Eq. 5; Eq. 8 for a soft-particle).
  double kt() const { return model->kt(*constants, k, geometry()); }
  /// The spring's elastic energy, 1/2 kt |xi|^2 [J] (0 without friction).
  double spring_energy() const { return spring ? tsuji::energy(kt(), v3(*spring)) : 0.0; }
  /// The length the overlap is measured against (the smaller sphere's radius; a soft-particle's
  /// contact: its law's R, so that h over it is Δn).
  double overlap_scale(const Particles& p) const {
    const double r_min = j >= 0 ? std::min(p.r[static_cast<std::size_t>(i)], p.r[static_cast<std::size_t>(j)]) : p.r[static_cast<std::size_t>(i)];
    return model->overlap_scale(*constants, k, r_min);
  }
};

/// Calls f(const ClosedContact&) for every contact of one family (run by `model`) with h > 0.
template <class F>
void for_each_closed_in_family(const World& world, const ContactFamily& lists, const SceneModel& model, F&& f) {
  const Particles& p = world.p;
  const PairList& pairs = lists.pairs;
  const auto body = [&](int i) { return lists.body_state.empty() ? 0.0 : lists.body_state[static_cast<std::size_t>(i)]; };
  const auto stress = [&](int i) {
    const auto s = static_cast<std::size_t>(i);
    return lists.body_stress.empty() ? BodyStress{} : BodyStress{&lists.body_stress[s], p.r[s]};
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int i = pairs.i[k], j = pairs.j[k];
    const Vec3 d = p.x[i] - p.x[j];
    const double dist = d.norm(), h = pairs.r_sum[k] - dist;
    if (!(h > 0.0)) continue;
    ClosedContact c{ClosedContact::Kind::pair, i, j, -1, h, &model, &pairs.k, k, pairs.spring.empty() ? nullptr : &pairs.spring[k]};
    c.body1 = body(i), c.body2 = body(j), c.n = v3(Vec3(d * (1.0 / dist)));  // as the force loop's
    c.stress1 = stress(i), c.stress2 = stress(j);
    f(std::as_const(c));
  }
  const auto walls = [&](const auto& shapes, const std::vector<WallList>& wall_lists, ClosedContact::Kind kind) {
    for (std::size_t w = 0; w < shapes.size(); ++w) {
      const WallList& l = wall_lists[w];
      for (std::size_t k = 0; k < l.size(); ++k) {
        const int i = l.i[k];
        const double h = shapes[w].overlap(p.x[i], p.r[i]);
        if (!(h > 0.0)) continue;
        ClosedContact c{kind, i, -1, static_cast<int>(w), h, &model, &l.k, k, l.spring.empty() ? nullptr : &l.spring[k]};
        c.body1 = body(i), c.stress1 = stress(i);
        if constexpr (std::is_same_v<std::decay_t<decltype(shapes[w])>, PlaneWall>) c.n = v3(shapes[w].normal);
        else c.n = v3(Vec3(-(p.x[i] - shapes[w].centre).normalized()));  // inwards
        f(std::as_const(c));
      }
    }
  };
  walls(world.planes, lists.planes, ClosedContact::Kind::plane);
  walls(world.shells, lists.shells, ClosedContact::Kind::shell);
}

/// Calls f(const ClosedContact&) for every contact with h > 0, family by family.
template <class F>
void for_each_closed_contact(const World& world, const ContactLists& lists, const ForceField& forces, F&& f) {
  for (std::size_t m = 0; m < lists.family.size() && m < forces.models(); ++m)
    for_each_closed_in_family(world, lists.family[m], forces.model(m), f);
}

}  // namespace softpack
