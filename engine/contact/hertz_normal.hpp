// Hertz normal contact law, paper Eq. 3-4: the normal law the engine runs (`effects.normal:
// hertz`, registered in forces/contact_models.cpp as contact/tsuji_model.hpp TsujiModel<HertzNormal>).
//
//   Fn = sqrt(R12) h^(3/2) / D,   R12 = R1 R2 / (R1 + R2),   D from Eq. 4 (core/material.hpp)
//
// Inputs: reduced radius R12 [m], overlap h [m] (h > 0 in contact), D [1/Pa]. The per-contact
// stiffness kn = sqrt(R12) / D [N/m^(3/2)] is computed once per contact, so that the force loop
// evaluates Fn = kn h^(3/2) with the square root of h it shares with the tangential law.
//
// A normal law is a value type with these members (docs/architecture.md, "Adding a normal law"):
//   name                       the scene's `effects.normal` value
//   stiffness(R12, D)          the per-contact constant kn
//   force(kn, h, sqrt_h)       Fn [N], a template over the number type (double or simd::Wide)
//   damping_scale(sqrt_h)      g(h) of the normal damping gamma_n = gamma0 g(h)
//   energy(kn, h)              elastic energy of the contact [J], the integral of Fn dh
//   damping_coefficient(e)     the zeta of gamma0 = zeta sqrt(m12 kn) that gives restitution e
//
// A law whose force on one contact depends on all of a body's contacts declares a body state
// (contact/contact_model.hpp BodyStateModel), which a pass before the forces accumulates over each
// sphere's closed contacts, in list order (forces/compile_loops.hpp):
//   kBodyState = true
//   body_term(h)                  what one closed contact adds to the state of each of its spheres
//   force(kn, h, sqrt_h, s1, s2)  Fn with the states of body 1 and body 2 (a wall's: 0)
//   energy(kn, h, s1, s2)         the elastic energy at those states
// (tests/physics/test_normal_law_registry.cpp registers one.)
#pragma once
#include <cmath>

#include "contact/viscous_damping.hpp"
#include "simd/wide.hpp"

namespace softpack {

struct HertzNormal {
  static constexpr const char* name = "hertz";

  /// kn = sqrt(R12) / D, so that Fn = kn h^(3/2).
  static double stiffness(double R12, double D) { return std::sqrt(R12) / D; }

  /// Eq. 3: Fn = kn h^(3/2) [N], h > 0.
  template <class T>
  [[gnu::always_inline]] static T force(const T& kn, const T& h, const T& sqrt_h) {
    return kn * h * sqrt_h;
  }

  /// Tsuji's damping of a Hertz contact: gamma_n = zeta sqrt(m12 kn) h^(1/4).
  template <class T>
  [[gnu::always_inline]] static T damping_scale(const T& sqrt_h) {
    return simd::sqrt(sqrt_h);
  }

  /// Elastic energy stored in the contact: integral of Fn dh = 2/5 kn h^(5/2) [J].
  static double energy(double kn, double h) { return 0.4 * kn * h * h * std::sqrt(h); }

  /// With the h^(1/4) factor the restitution depends on zeta alone (contact/viscous_damping.hpp).
  static double damping_coefficient(double restitution) { return damping::zeta_from_restitution(restitution); }
};

namespace hertz {

/// R12 = R1 R2 / (R1 + R2); a plane wall is a sphere of infinite radius, R12 = R1.
inline double reduced_radius(double R1, double R2) { return R1 * R2 / (R1 + R2); }

/// R12 of a sphere of radius r touching the inside of a concave spherical shell of radius Rs:
/// the shell's curvature is negative, 1/R12 = 1/r - 1/Rs, so R12 = r Rs / (Rs - r).
inline double reduced_radius_concave(double r, double Rs) { return r * Rs / (Rs - r); }

}  // namespace hertz

}  // namespace softpack
