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
//   5. on separation xi is cleared (done by the contact list).
#pragma once
#include <cmath>

#include "core/types.hpp"

namespace softpack::tsuji {

/// Per-contact constant kt0 = Dt sqrt(R12), so that the stiffness is kt = kt0 sqrt(h) [N/m].
[[gnu::always_inline]] inline double stiffness_factor(double R12, double Dt) { return Dt * std::sqrt(R12); }

/// Step 1: project xi onto the plane normal to the unit vector n and restore its length.
/// With s = (xi.n)^2 / |xi|^2 the length is restored by the factor 1/sqrt(1 - s); between two
/// steps the frame turns little and s is tiny, where the series 1 + s/2 + 3s^2/8 equals that
/// factor to rounding (next term 5s^3/16 < 1e-19 for s < 1e-6) and spares a square root.
[[gnu::always_inline]] inline void rotate_into_tangent_plane(Vec3& xi, const Vec3& n) {
  const double len2 = xi.squaredNorm();
  if (len2 == 0.0) return;
  const double c = xi.dot(n);
  const double s = c * c / len2;
  if (s >= 1.0) {  // xi along n: no tangential direction left to keep
    xi.setZero();
    return;
  }
  xi -= c * n;
  xi *= s < 1e-6 ? 1.0 + s * (0.5 + 0.375 * s) : 1.0 / std::sqrt(1.0 - s);
}

/// Steps 3-4: tangential force on the first body from spring xi, stiffness kt [N/m],
/// tangential damping gamma_t [kg/s], tangential velocity vt and the Coulomb limit mu Fn.
/// Updates xi when the contact slides. Returns Ft.
[[gnu::always_inline]] inline Vec3 force(Vec3& xi, double kt, double gamma_t, const Vec3& vt, double mu_Fn) {
  Vec3 Ft = -kt * xi - gamma_t * vt;
  const double Ft2 = Ft.squaredNorm();
  if (Ft2 > mu_Fn * mu_Fn) {  // Eq. 5 cap: slide at mu Fn, spring shortened to match
    Ft *= mu_Fn / std::sqrt(Ft2);
    xi = -Ft / kt;
  }
  return Ft;
}

/// Elastic energy of the spring, 1/2 kt |xi|^2 [J].
[[gnu::always_inline]] inline double energy(double kt, const Vec3& xi) { return 0.5 * kt * xi.squaredNorm(); }

}  // namespace softpack::tsuji
