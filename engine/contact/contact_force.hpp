// The force routine every contact goes through (sphere-sphere, sphere-plane, sphere-shell), in
// a fixed order: geometry (given) -> spring history (advance_spring) -> Hertz normal (Eq. 3)
// -> normal damping -> Coulomb limit and tangential spring (Eq. 5). It is a template over the declared effects, so a scene
// without friction or damping compiles a loop without them.
//
// Conventions: n is the unit normal pointing from body 2 to body 1, h > 0 the overlap, and
// vc the velocity of body 1 relative to body 2 at the contact point (rotation included).
// The returned forces act on body 1; body 2 receives the opposite.
#pragma once
#include <cmath>

#include "contact/hertz_normal.hpp"
#include "contact/tsuji_tangential.hpp"
#include "core/types.hpp"

namespace softpack {

/// Constants of one contact, fixed while it lasts (they depend only on the two spheres).
struct ContactCoefficients {
  double kn = 0.0;      ///< sqrt(R12)/D, Fn = kn h^(3/2)            (Eq. 3)
  double kt0 = 0.0;     ///< Dt sqrt(R12), kt = kt0 sqrt(h)           (Eq. 5)
  double gamma0 = 0.0;  ///< alpha sqrt(m12 kn), gamma_n = gamma0 h^(1/4)
  double gamma_t0 = 0.0;  ///< ratio_t alpha sqrt(mt kt0), gamma_t = gamma_t0 h^(1/4)
  double mu = 0.0;      ///< Coulomb coefficient
};

struct ContactForce {
  Vec3 F;             ///< total force on body 1
  Vec3 Ft;            ///< its tangential part (for the torques)
  double Fn_elastic;  ///< Hertz force of Eq. 3, the Coulomb limit's Fn
};

/// Carries the tangential spring `xi` of a closed contact over one step (Eq. 5 history):
/// rotated into the tangent plane of `n_frame` keeping its length, incremented by the
/// tangential part of the contact-point velocity `vc_frame` times dt, then rotated into the
/// plane of the current normal `n` (a no-op when the frames coincide, as with the `standard`
/// history update; see scene/scene_def.hpp HistoryUpdate).
[[gnu::always_inline]] inline void advance_spring(Vec3& xi, const Vec3& n_frame, const Vec3& vc_frame, const Vec3& n, double dt) {
  tsuji::rotate_into_tangent_plane(xi, n_frame);
  xi += (vc_frame - vc_frame.dot(n_frame) * n_frame) * dt;
  tsuji::rotate_into_tangent_plane(xi, n);
}

/// Force on body 1 of a closed contact. `xi` is the contact's tangential spring, already
/// advanced to this step (advance_spring); it is shortened here when the contact slides.
template <bool Friction, bool Damping>
[[gnu::always_inline]] inline ContactForce contact_force(const Vec3& n, double h, const Vec3& vc, const ContactCoefficients& k, Vec3& xi) {
  const double sqrt_h = std::sqrt(h);
  const double Fn = k.kn * h * sqrt_h;  // Eq. 3
  const double vn = vc.dot(n);
  double h_quarter = 0.0;
  double F_normal = Fn;
  if constexpr (Damping) {
    h_quarter = std::sqrt(sqrt_h);
    F_normal -= k.gamma0 * h_quarter * vn;  // gamma_n = alpha sqrt(m12 kn) h^(1/4)
  }
  ContactForce out{F_normal * n, Vec3::Zero(), Fn};
  if constexpr (Friction) {
    const Vec3 vt = vc - vn * n;
    const double kt = k.kt0 * sqrt_h;  // Eq. 5: sqrt(R12 h) Dt
    const double gamma_t = Damping ? k.gamma_t0 * h_quarter : 0.0;
    out.Ft = tsuji::force(xi, kt, gamma_t, vt, k.mu * Fn);  // Coulomb limit, Eq. 5
    out.F += out.Ft;
  }
  return out;
}

}  // namespace softpack
