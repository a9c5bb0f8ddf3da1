// The soft-particle contact law: a soft-particle (a local packing in its shell, paper §2) run as
// one rigid sphere whose contacts follow the laws measured on it (formats/law_file.hpp reads
// them from the law file; scene key effects.soft_particles):
//
//   Fn = S_F (a Δn^b + c)     for Δn >= δ, 0 below          (paper Eq. 7)
//   kt = S_t (a' Δn^b' + c')  for Δn >= δ, 0 below          (Eq. 8, kt in N/m of ht)
//   Ft = -kt ξ,  |Ft| <= μ_soft(Δn) Fn                       (the measured sliding ratio)
//
// with Δn = h / R, h the overlap of the two spheres (of the sphere and the wall), and the radius
// scaling S_F = (R/R0)^n_F, S_t = (R/R0)^n_t at fixed Δn (docs/radius.md). Which law and which R:
//
//   soft-particle - plane wall       soft-solid law, R = the soft-particle's radius
//   soft-particle - soft-particle    soft-soft law, R = R1 for equal radii; else the law file's
//                                    mixing rule: R = R_eq = 2 R1 R2 / (R1 + R2)
//   soft-particle - solid sphere     soft-solid law (measured against a wall, a solid sphere of
//                                    infinite radius); the scene chooses R (GrainContactRule):
//                                    `wall` R = Rs (the grain is taken as flat), or
//                                    `reduced-radius` R = Rs r / (Rs + r) (-> Rs as r -> inf)
//
// A negative value of a fit just above δ (c not exactly -a δ^b) is taken as 0. The spring ξ is
// the Tsuji spring of contact/tsuji_tangential.hpp (same history rules); only its stiffness and
// Coulomb limit come from the measurement. Damping (when the scene declares it): the linear
// spring's viscous damping at the contact's current stiffness, γn = 2 ζ sqrt(m12 dFn/dh),
// γt = ratio_t 2 ζ sqrt(mt kt), with ζ = -ln e / sqrt(π² + ln² e) from the scene's restitution e.
//
// The laws hold on the Δn range they were measured on; beyond it they are evaluated as written
// and the contact is counted (SoftContactStats) or, with `beyond_range: stop`, stops the run.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_law.hpp"
#include "core/types.hpp"

namespace softpack {

/// X(Δn) = a Δn^b + c for Δn >= δ, 0 below (and 0 where that is negative): Eq. 7 and Eq. 8.
struct SoftPowerLaw {
  double a = 0.0, b = 1.0, c = 0.0, delta = 0.0;
  double dn_min = 0.0, dn_max = 0.0;  ///< the Δn range it was measured on

  double operator()(double dn) const {
    if (!(dn >= delta)) return 0.0;
    const double x = a * std::pow(dn, b) + c;
    return x > 0.0 ? x : 0.0;
  }
  /// dX/dΔn (0 where X is 0).
  double slope(double dn) const { return (*this)(dn) > 0.0 ? a * b * std::pow(dn, b - 1.0) : 0.0; }
  /// ∫ X dΔn from δ to Δn (where X > 0; exact for c = -a δ^b).
  double integral(double dn) const;
};

/// The laws of one measurement scene (soft-solid or soft-soft) at the reference radius R0.
struct SoftSceneLaw {
  SoftPowerLaw normal;                     ///< Fn [N] (Eq. 7)
  std::optional<SoftPowerLaw> tangential;  ///< kt [N/m] (Eq. 8); needed with friction
  std::vector<double> mu_dn, mu;           ///< μ_soft at increasing Δn; needed with friction
  std::optional<double> normal_exponent, tangential_exponent;  ///< n_F, n_t (none: R must be R0)
  double R_min = 0.0, R_max = 0.0;                             ///< radii the scaling was measured at [m]

  /// μ_soft(Δn): linear between the measured Δn, the end values outside.
  double mu_at(double dn) const;
};

/// How a soft-particle meets a solid sphere (no measurement of that scene yet; see the header).
enum class GrainContactRule { wall, reduced_radius };

/// What the soft-particle contacts run on: the law file's content (and where it came from).
struct SoftParticleLaws {
  double R0 = 0.0;  ///< reference radius [m]
  std::optional<SoftSceneLaw> soft_solid, soft_soft;
  std::string source;  ///< the law file, for messages and provenance
};

enum class SoftContactKind : std::uint8_t { wall, grain, soft };

/// Constants of one soft-particle contact, fixed while it lasts.
struct SoftContactConstants {
  const SoftSceneLaw* law = nullptr;
  double R = 0.0;                     ///< Δn = h / R [m]
  double F_scale = 1.0, kt_scale = 1.0;  ///< (R/R0)^n_F, (R/R0)^n_t
  double m12 = 0.0, mt = 0.0;         ///< reduced mass, sliding-rolling mass [kg] (damping)
};

/// The law, R and scales of a contact of kind `kind` between a soft-particle of radius R1 and
/// a body of radius R2 (ignored for a wall).
SoftContactConstants soft_contact_constants(const SoftParticleLaws& laws, SoftContactKind kind, GrainContactRule grain_rule,
                                            double R1, double R2, double m12, double mt);

/// ζ of the linear spring's viscous damping that gives restitution e (0 < e <= 1).
double linear_damping_ratio(double e);

/// The declared effects a soft-particle contact runs (the scene's, read at run time).
struct SoftEffects {
  bool friction = false, damping = false;
  double zeta = 0.0, tangential_ratio = 1.0;
};

/// Force on body 1 of a closed soft-particle contact (conventions of contact/contact_law.hpp:
/// n from body 2 to body 1, h > 0, vc of body 1 relative to body 2). `xi` is advanced by dt and
/// shortened when the contact slides. Fn is the law's elastic force; `dn` receives Δn.
ContactForce<double> soft_contact_force(const ContactGeometry<double>& g, const SoftContactConstants& k, const SoftEffects& fx,
                                        V3<double>& xi, double dt, double& dn);

/// Elastic energy of a soft-particle contact: ∫ Fn dh = S_F R ∫ X dΔn, plus 1/2 kt |ξ|² [J].
double soft_contact_energy(const SoftContactConstants& k, double h, const Vec3* xi);
/// The law's Fn [N] and kt [N/m] of a contact at overlap h.
double soft_Fn(const SoftContactConstants& k, double h);
double soft_kt(const SoftContactConstants& k, double h);

}  // namespace softpack
