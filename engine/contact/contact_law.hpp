// The force of one contact, written once for every kind of contact and every number type.
//
// Sphere-sphere, sphere-plane and sphere-shell contacts (forces/*_contacts.hpp) supply only
// their geometry: normal, overlap, contact-point velocity (ContactGeometry). This routine does
// the rest, in a fixed order (as LAMMPS's GranularModel::calculate_forces()):
//
//   spring history (tsuji::advance_spring) -> normal law (Eq. 3) -> normal damping
//   -> tangential spring (Eq. 5) -> Coulomb limit
//
// It is a template over the normal law (contact/hertz_normal.hpp), over the declared effects
// (contact/effects.hpp: a loop without friction or damping holds none of their arithmetic) and
// over the number type: `double` for one contact, simd::Wide for eight at once, with the same
// bits per lane.
//
// Conventions: n is the unit normal pointing from body 2 to body 1, h > 0 the overlap, vc the
// velocity of body 1 relative to body 2 at the contact point (rotation included). The forces
// returned act on body 1; body 2 receives the opposite.
#pragma once
#include "contact/effects.hpp"
#include "contact/tsuji_tangential.hpp"
#include "simd/vec3.hpp"

namespace softpack {

/// What the kind of contact supplies, at the current step.
template <class T>
struct ContactGeometry {
  V3<T> n;   ///< unit normal, from body 2 to body 1
  T h;       ///< overlap [m], > 0
  V3<T> vc;  ///< contact-point velocity of body 1 relative to body 2 [m/s]
  /// The frame of the spring update and the contact-point velocity in it: n and vc with the
  /// `standard` history update, their half-step values with `synchronized` (friction only).
  V3<T> n_frame, vc_frame;
  /// The two bodies' states from the per-body pass, for a law that declares one (a wall's: 0).
  T body1, body2;
};

/// A normal law whose force reads the state of each body, accumulated over the body's closed
/// contacts by a pass before the forces (contact/hertz_normal.hpp lists what it declares; the
/// pattern of LAMMPS's EAM and MDR models).
template <class NormalLaw>
concept BodyStateLaw = NormalLaw::kBodyState;

/// Fn of the normal law (Eq. 3 for Hertz), with the bodies' states when it reads them.
template <class NormalLaw, class T>
[[gnu::always_inline]] inline T normal_force(const T& kn, const ContactGeometry<T>& g, const T& sqrt_h) {
  if constexpr (BodyStateLaw<NormalLaw>) return NormalLaw::force(kn, g.h, sqrt_h, g.body1, g.body2);
  else return NormalLaw::force(kn, g.h, sqrt_h);
}

/// Constants of one contact, fixed while it lasts (contact/coefficients.hpp makes them).
template <class T>
struct ContactConstants {
  T kn;        ///< normal law's stiffness (Hertz: sqrt(R12)/D, Fn = kn h^(3/2))
  T kt0;       ///< Dt sqrt(R12), kt = kt0 sqrt(h)                     (Eq. 5)
  T gamma0;    ///< zeta sqrt(m12 kn), gamma_n = gamma0 g(h)
  T gamma_t0;  ///< ratio_t zeta sqrt(mt kt0), gamma_t = gamma_t0 g(h)
  T mu;        ///< Coulomb coefficient
};

template <class T>
struct ContactForce {
  V3<T> F;   ///< total force on body 1 [N]
  V3<T> Ft;  ///< its tangential part (for the torques) [N]
  T Fn;      ///< the normal law's force, the Coulomb limit's Fn [N]
};

/// Force on body 1 of a closed contact. `xi` is the contact's tangential spring before the step;
/// it is advanced by `dt` (spring history) and shortened when the contact slides.
template <class NormalLaw, Effects Fx, class T>
[[gnu::always_inline]] inline ContactForce<T> contact_force(const ContactGeometry<T>& g, const ContactConstants<T>& k, V3<T>& xi,
                                                            double dt) {
  if constexpr (Fx.friction) tsuji::advance_spring(xi, g.n_frame, g.vc_frame, g.n, dt);
  const T sqrt_h = simd::sqrt(g.h);
  const T Fn = normal_force<NormalLaw>(k.kn, g, sqrt_h);  // Eq. 3
  const T vn = dot(g.vc, g.n);
  T F_normal = Fn;
  T g_h{};
  if constexpr (Fx.damping) {
    g_h = NormalLaw::damping_scale(sqrt_h);
    F_normal = F_normal - k.gamma0 * g_h * vn;  // gamma_n = gamma0 g(h)
  }
  ContactForce<T> out{F_normal * g.n, {T(0.0), T(0.0), T(0.0)}, Fn};
  if constexpr (Fx.friction) {
    const V3<T> vt = g.vc - vn * g.n;
    const T kt = k.kt0 * sqrt_h;  // Eq. 5: sqrt(R12 h) Dt
    const T gamma_t = Fx.damping ? k.gamma_t0 * g_h : T(0.0);
    out.Ft = -kt * xi - gamma_t * vt;
    tsuji::coulomb_limit(out.Ft, xi, kt, k.mu * Fn);  // Eq. 5 cap
    out.F = out.F + out.Ft;
  }
  return out;
}

}  // namespace softpack
