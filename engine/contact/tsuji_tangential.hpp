// Tsuji, Tanaka & Ishida (1992) tangential spring, paper Eq. 5-6:
//
//   Ft = sqrt(R12 h) Dt ht,   |Ft| <= mu Fn
//
// ht is the spring: the tangential displacement accumulated at the contact point while the
// contact is closed. We store the spring as a displacement vector xi (|xi| = ht), exactly the
// quantity of Eq. 5, rather than accumulated force increments. Consequence, chosen knowingly:
// the stiffness kt = Dt sqrt(R12 h) depends on the overlap, so at fixed xi the force follows
// the current overlap (the spring "stiffens" when pressed harder). For the paper's
// measurements, which hold hn fixed while shearing, the two choices give the same force; the
// displacement form is the one the paper writes down, and its Coulomb rule ("the spring
// length is set such that Ft = mu Fn") is stated for it.
//
// History rules, applied each step in this order (LAMMPS / MercuryDPM convention):
//   1. rotate xi into the tangent plane of the step (the half-step plane with the synchronized
//      update of Vyas et al. 2025, then on to the current plane), keeping its length;
//   2. add the relative tangential displacement of this step, vt dt (rotation included);
//   3. trial force Ft = -kt xi - gamma_t vt;
//   4. if |Ft| > mu Fn: Ft = mu Fn Ft/|Ft| and xi = -Ft / kt (spring shortened to match);
//   5. on separation xi is cleared (done by the force loop, forces/contact_loop.hpp).
//
// Every function is a template over the number type: one contact (double) or eight (simd::Wide).
#pragma once
#include <cmath>

#include "simd/vec3.hpp"

namespace softpack::tsuji {

/// Per-contact constant kt0 = Dt sqrt(R12), so that the stiffness is kt = kt0 sqrt(h) [N/m].
inline double stiffness_factor(double R12, double Dt) { return Dt * std::sqrt(R12); }

/// Step 1: project xi onto the plane normal to the unit vector n and restore its length.
/// With s = (xi.n)^2 / |xi|^2 the length is restored by the factor 1/sqrt(1 - s); between two
/// steps the frame turns little and s is tiny, where the series 1 + s/2 + 3s^2/8 equals that
/// factor to rounding (next term 5s^3/16 < 1e-19 for s < 1e-6) and spares a square root and a
/// division: they are computed only when a contact needs them. A zero spring stays zero; one
/// along n (s >= 1) has no tangential direction left and is cleared.
template <class T>
[[gnu::always_inline]] inline void rotate_into_tangent_plane(V3<T>& xi, const V3<T>& n) {
  const T len2 = dot(xi, xi);
  const T c = dot(xi, n);
  const T s = simd::select(len2 != T(0.0), c * c / len2, T(0.0));
  T factor = T(1.0) + s * (T(0.5) + T(0.375) * s);
  const auto beyond_series = s >= T(1e-6);
  if (simd::any(beyond_series)) factor = simd::select(beyond_series, T(1.0) / simd::sqrt(T(1.0) - s), factor);
  const auto keep = len2 == T(0.0), clear = s >= T(1.0);
  const V3<T> zero{T(0.0), T(0.0), T(0.0)};
  xi = select(keep, xi, select(clear, zero, (xi - c * n) * factor));
}

/// Steps 1-2: xi into the tangent plane of the update frame f, plus the tangential part of the
/// contact-point velocity u there times dt, then into the plane of the current normal n (a
/// no-op when the frames coincide, with the `standard` history update).
template <class T>
[[gnu::always_inline]] inline void advance_spring(V3<T>& xi, const V3<T>& f, const V3<T>& u, const V3<T>& n, double dt) {
  rotate_into_tangent_plane(xi, f);
  const T un = dot(u, f);
  xi = xi + (u - un * f) * T(dt);
  rotate_into_tangent_plane(xi, n);
}

/// Step 4, the Coulomb limit: where |Ft|^2 = Ft2 exceeds (mu Fn)^2, Ft is scaled to mu Fn and
/// the spring shortened to match, xi = -Ft / kt; elsewhere both stay as they are.
template <class T>
[[gnu::always_inline]] inline void coulomb_limit(V3<T>& Ft, V3<T>& xi, const T& kt, const T& mu_Fn) {
  const T Ft2 = dot(Ft, Ft);
  const auto slide = Ft2 > mu_Fn * mu_Fn;
  if (!simd::any(slide)) return;
  Ft = Ft * simd::select(slide, mu_Fn / simd::sqrt(Ft2), T(1.0));
  xi = select(slide, -Ft / kt, xi);
}

/// Elastic energy of the spring, 1/2 kt |xi|^2 [J].
inline double energy(double kt, const V3<double>& xi) { return 0.5 * kt * dot(xi, xi); }

}  // namespace softpack::tsuji
