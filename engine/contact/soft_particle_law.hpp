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
// and the contact is counted (forces/contact_models.hpp RangeStats) or, with `beyond_range: stop`,
// stops the run.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/tsuji_tangential.hpp"
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
  /// Where X becomes positive: δ for c = -a δ^b, later when a fit's c is more negative.
  double start() const { return c < 0.0 ? std::max(delta, std::pow(-c / a, 1.0 / b)) : delta; }
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

/// ζ of the linear spring's viscous damping that gives restitution e (0 < e <= 1).
double linear_damping_ratio(double e);

/// How a soft-particle meets a solid sphere (no measurement of that scene yet; see the header).
enum class GrainContactRule { wall, reduced_radius };  // int, as contact/contact_model.hpp declares it

/// The many-body law (issue 33; paper/many-body.md; the law file's `many_body`, version 2): a
/// soft-particle's contacts share its volumetric strain. With v(δ) = δ² (3 − δ) / 4 the volume of
/// a cap of depth δ R over the soft-particle's, a(δ) = 2δ − δ² its base over π R², and E the sum
/// of v(Δn) over the soft-particle's closed contacts (the per-body pass), contact k carries
///
///   Fn_k = S_F X(δ*) a(Δn_k) / a(δ*),   v(δ*) = v(Δn_k) + β (E − v(Δn_k))
///
/// (X: Eq. 7 of the contact's scene): the pressure p(v(δ)) = X(δ) / a(δ) that one contact of
/// volume v(δ) makes, at the strain of all the contacts, β of the others' counted, on this
/// contact's cap. One contact (E = v(Δn_k)) gives Eq. 7 exactly. Measured against walls (the probe,
/// `make many-body-probe`); between two soft-particles E − v(Δn_k) is the mean of their two (the
/// third version's β_ss fitted with that rule on the probe's soft arrangements).
struct ManyBodyLaw {
  double beta = 0.0;  ///< β, of the other contacts' cap volumes counted (a wall's; any contact's without its own)
  /// kt times the contact's normal gain Fn / Eq. 7 (the confined shear of the probe: kt grows with
  /// confinement as Fn does; a grain's g included, unmeasured); false: kt as measured on one contact (Eq. 8).
  bool tangential_gain = false;
  // The third version (law file version 3; paper/many-body.md): E the union of the caps instead
  // of their sum (cap_union_volume); a solid sphere of radius r presses with g(r/R) =
  // ((r/R) / (1 + r/R))^grain_exponent of Eq. 7 and its own β; two soft-particles with their own β.
  bool union_of_caps = false;
  double grain_exponent = 0.0;
  std::optional<double> grain_beta{}, soft_beta{};
  /// The stress term of soft-soft contacts (law file version 4, many_body.soft_soft.stress; paper/many-body.md,
  /// "the soft-soft push carried by the neighbours' stress"): a contact k between soft-particles i and j carries
  ///
  ///   Fn_k = Fn_base + κ π R² a(Δn_k) (p_i + p_j) / 2,
  ///
  /// Fn_base the force above, R the contact's R, and p_i the stress on soft-particle i (radius R_i)
  /// from its other contacts, with S_i = Σ Fn_base n ⊗ n over i's closed contacts (the stress pass):
  ///
  ///   mean      p_i = (tr S_i − Fn_base,k) / (4π R_i²)
  ///   normal    p_i = 3 (n·S_i·n − Fn_base,k) / (4π R_i²)        (along the contact's normal)
  ///   lateral   p_i = 3 (tr S_i − n·S_i·n) / (2 · 4π R_i²)       (across it)
  ///
  /// each taken as 0 where rounding makes it negative. Other contacts carry none.
  struct SoftStress {
    enum class Form { mean, normal, lateral };
    Form form = Form::mean;
    double kappa = 0.0;  ///< κ
  };
  std::optional<SoftStress> soft_stress{};
};

/// v(δ) = δ² (3 − δ) / 4: a cap of depth δ R of a sphere of radius R, over the sphere's volume.
template <class T>
[[gnu::always_inline]] inline T cap_volume(const T& d) {
  return d * d * (T(3.0) - d) / T(4.0);
}
/// a(δ) = 2δ − δ² up to the hemisphere, 1 past it (δ > 1): the cap's base area over π R², the
/// area a contact's pressure acts on. Past the centre a plane's section shrinks again, to 0 at
/// δ = 2, and the pressure X(δ*)/a(δ*) of the many-body law would have a pole there (a soft-
/// particle whose caps fill it; docs/nested.md, "the chain's level 1 blow-up"): a squeezed
/// soft-particle keeps at least its equator's area.
inline double cap_area(double d) { return d < 1.0 ? 2.0 * d - d * d : 1.0; }
/// The meridians of the union of caps, the engine's and the probe analysis's (tests/physics
/// ManyBodySoftParticles.TheCapsUnionIsExactWhereItIsKnown measures what they miss).
inline constexpr int kCapUnionMeridians = 256;
/// The volume the caps of depths δ_k R along the unit directions n_k cut from a sphere of radius R
/// together (their union), over the sphere's volume: v(δ) for one cap, Σ v(δ_k) for caps that do
/// not meet. A ray from the centre along u leaves the sphere's union of caps at r = 1 and enters
/// cap k at r_k = (1 − δ_k) / (u·n_k); it is in cap k's share where r_k is the least, a region
/// of the directions bounded by great circles (r_k < r_l is u·((1 − δ_l) n_k − (1 − δ_k) n_l) > 0).
/// Along each meridian of cap k that share is an interval of polar angle, over which the radial
/// integral is exact; the meridians are summed by the periodic trapezoid rule (`meridians` of
/// them, a positive multiple of 8, else std::invalid_argument; only for caps another one meets),
/// eight meridians at once on the processor's vector lanes. δ_k is taken in [0, 1 − 1e-9] (the
/// plane short of the centre). Deterministic: the same bits for the same caps in the same order,
/// on any instruction set.
double cap_union_volume(const std::vector<Vec3>& n, const std::vector<double>& depth, int meridians = kCapUnionMeridians);
/// δ in [0, 2] with v(δ) = eps (0 for eps <= 0, 2 for eps >= 1): the cubic's trigonometric root,
/// polished by Newton's method to within a few units of the last place.
double cap_depth(double eps);
/// The many-body law's force (ManyBodyLaw) of a contact at Δn = dn whose soft-particle's other
/// contacts hold the cap volume `others`, from the single-contact law X (a callable of Δn), times
/// `scale`: scale X(δ*) a(dn) / a(δ*); with no other contact scale X(dn), as it is. Where the caps
/// reach the ball's volume (v(dn) + β others >= 1) δ* is 2: the force is scale X(2) a(dn), the limit
/// of the formula (continuous, with a(δ) bounded past the hemisphere: cap_area). The engine's
/// model and the many-body probe's analysis (studies/coarse/probe_fit.hpp) both call it.
template <class Law>
double many_body_force(const Law& X, double scale, double dn, double others, double beta) {
  if (!(others > 0.0) || !(dn > 0.0)) return scale * X(dn);
  const double star = cap_depth(cap_volume(dn) + beta * others);
  return star > 0.0 ? scale * X(star) * cap_area(dn) / cap_area(star) : scale * X(dn);
}

/// What the soft-particle contacts run on: the law file's content (and where it came from).
struct SoftParticleLaws {
  double R0 = 0.0;  ///< reference radius [m]
  std::optional<SoftSceneLaw> soft_solid, soft_soft;
  std::optional<ManyBodyLaw> many_body;  ///< the law file's (version 2); none: the pairwise laws
  std::string source;  ///< the law file, for messages and provenance
};

/// The soft-particle contact model (contact/contact_model.hpp), written for one contact at a
/// time (kScalarOnly): its normal sub-law (Eq. 7 at the contact's R), the linear spring's
/// damping at the contact's current stiffness, and the measured tangential stiffness (Eq. 8)
/// with mu_soft on the Tsuji spring.
struct SoftNormal {
  static constexpr const char* name = "soft-particle";
  static constexpr bool kScalarOnly = true;
  static constexpr double kSoftSolid = 0.0, kSoftSoft = 1.0;  ///< Constants::scene: which measured law

  template <class T>
  struct Constants {
    T scene;    ///< the law: kSoftSolid or kSoftSoft (a constant like the others, so a double)
    T R;        ///< Δn = h / R [m]
    T F_scale;  ///< (R/R0)^n_F
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.scene, Need::always);
    f(c.R, Need::always);
    f(c.F_scale, Need::always);
  }
  struct Params {
    const SoftParticleLaws* laws = nullptr;
    GrainContactRule grain_rule = GrainContactRule::wall;
    bool stop_beyond_range = false;
    const SoftSceneLaw& law(double scene) const { return scene == kSoftSoft ? *laws->soft_soft : *laws->soft_solid; }
  };
  static Params params(const ContactSetting& s) { return {s.soft_laws, s.grain_rule, s.stop_beyond_range}; }
  /// Which law and which R (the header): body 1 or body 2 is a soft-particle.
  static Constants<double> constants(const Params& p, const ContactPartners& b);

  struct Eval {
    double Fn;  ///< Eq. 7 at R
    double dn;  ///< Δn
    const SoftSceneLaw* law;
    const Constants<double>* k;
    double gain;  ///< Fn over Eq. 7's (the many-body law's; 1 here)
    /// dFn/dh [N/m] (the damping's): Eq. 7's, times the gain.
    double stiffness() const { return gain * (k->F_scale * law->normal.slope(dn) / k->R); }
  };
  static Eval evaluate(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g) {
    const SoftSceneLaw& law = p.law(k.scene);
    const double dn = g.h / k.R;
    return {k.F_scale * law.normal(dn), dn, &law, &k, 1.0};
  }
  /// ∫ Fn dh = S_F R ∫ X dΔn [J].
  static double energy(const Params& p, const Constants<double>& k, double h, double, double) {
    return k.F_scale * k.R * p.law(k.scene).normal.integral(h / k.R);
  }
  /// The length an overlap is measured against: Δn = h / R.
  static double overlap_scale(const Constants<double>& k) { return k.R; }
  /// The law whose Δn range (dn_min, dn_max) it was measured on: a contact beyond it is counted
  /// (forces/contact_models.hpp RangeStats) or, with `beyond_range: stop`, stops the run.
  static const SoftPowerLaw& measured(const Params& p, const Constants<double>& k) { return p.law(k.scene).normal; }
  static const std::string& source(const Params& p) { return p.laws->source; }
  static constexpr const char* kStopKey = "effects.soft_particles.beyond_range is 'stop'";
};

/// The many-body soft-particle contact model's normal sub-law (ManyBodyLaw above): the
/// soft-particle law's constants and one more, which body is a soft-particle, and a body state,
/// each body's E, summed over its closed contacts before the forces.
struct SoftManyBodyNormal : SoftNormal {
  static constexpr const char* name = "soft-particle-many-body";
  static constexpr bool kBodyState = true;
  static constexpr double kBody1 = 1.0, kBody2 = 2.0, kBoth = 3.0;  ///< Constants::soft

  static constexpr bool kBodyCaps = true;
  static constexpr bool kBodyStress = true;  ///< with the law's soft_stress (contact/contact_model.hpp BodyStressModel)

  template <class T>
  struct Constants : SoftNormal::Constants<T> {
    T soft;   ///< the soft-particle: body 1, body 2 or both (kBody1, kBody2, kBoth)
    T beta;   ///< β of this contact's kind: a wall's, a grain's, two soft-particles'
    T scale;  ///< of Eq. 7: a grain's g(r / R) (1 for the others)
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    SoftNormal::each_constant(c, f);
    f(c.soft, Need::always);
    f(c.beta, Need::always);
    f(c.scale, Need::always);
  }
  static Constants<double> constants(const Params& p, const ContactPartners& b);
  /// What a closed contact adds to each of its bodies' E: v(Δn).
  template <class T>
  [[gnu::always_inline]] static T body_term(const T& h, const Constants<T>& k) {
    return cap_volume(h / k.R);
  }
  /// With the union form (ManyBodyLaw::union_of_caps) a body's E is made from its closed
  /// contacts' caps (direction, depth Δn) after the pass: body_state(caps).
  static bool body_caps(const Params& p) { return p.laws->many_body->union_of_caps; }
  template <class T>
  [[gnu::always_inline]] static T cap_depth_of(const T& h, const Constants<T>& k) {
    return h / k.R;
  }
  /// Whether body `body` (1 or 2) of lane m's contact keeps the cap: a soft-particle's (a grain's
  /// state is never read).
  template <class W>
  [[gnu::always_inline]] static bool keeps_cap(const Constants<W>& k, int m, int body) {
    return k.soft.v[m] == kBoth || k.soft.v[m] == body;
  }
  static double body_state(const std::vector<Vec3>& u, const std::vector<double>& depth) { return cap_union_volume(u, depth); }
  /// Whether the stress pass runs: the law has a stress term (ManyBodyLaw::soft_stress).
  static bool body_stress(const Params& p) { return p.laws->many_body->soft_stress.has_value(); }
  /// The force: Fn_base at the bodies' states, plus, for two soft-particles whose stress tensors g
  /// carries, the stress term (ManyBodyLaw::SoftStress). The gain (Fn over Eq. 7's, the tangential
  /// gain's) and the Coulomb limit see the whole Fn; the damping's stiffness (Eval::stiffness) is
  /// Eq. 7's dFn/dh times that gain: the stress term scales it as it scales the force (its own
  /// slope in h, through a(Δn), is not added: the neighbours' stress is taken as a given load).
  static Eval evaluate(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g);
  /// ∫ Fn_base dh from 0 to h with the other contacts' caps as they are (the stress term, not the
  /// derivative of a potential, is left out): Eq. 7's integral for a contact
  /// alone (the pairwise model's), else Simpson's rule on kEnergyIntervals from where the force
  /// starts (tests/physics ManyBodySoftParticles.TheEnergyIsTheForcesIntegral); past the
  /// hemisphere (δ* > 1) and where the caps fill the ball (δ* = 2) the force has kinks the rule
  /// does not place a node on.
  static constexpr int kEnergyIntervals = 16;
  static double energy(const Params& p, const Constants<double>& k, double h, double s1, double s2);

 private:
  /// E − v over the soft body (the mean of the two for two soft-particles).
  static double others(const Constants<double>& k, double v, double s1, double s2);
  /// Fn at Δn = dn with the other contacts' caps `others`.
  static double force(const Params& p, const Constants<double>& k, double dn, double others);
  /// p_i of a soft-particle of tensor S and radius R along n, this contact's base force Fn (SoftStress).
  static double stress_on(ManyBodyLaw::SoftStress::Form form, const SymmetricTensor& S, double R, const V3<double>& n, double Fn);
};

/// The damping of a soft-particle contact (when the scene declares it): the linear spring's at
/// the contact's current stiffness, gamma_n = 2 zeta sqrt(m12 dFn/dh), gamma_t = ratio_t 2 zeta
/// sqrt(mt kt), zeta = -ln e / sqrt(pi^2 + ln^2 e).
struct SoftDamping {
  template <class T>
  struct Constants {
    T m12;  ///< reduced mass [kg]
    T mt;   ///< sliding-rolling mass [kg]
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.m12, Need::damping);
    f(c.mt, Need::friction_damping);
  }
  struct Params {
    double zeta = 0.0, tangential_ratio = 1.0;
  };
  static Params params(const ContactSetting& s) { return {s.restitution ? linear_damping_ratio(*s.restitution) : 0.0, s.tangential_ratio}; }
  template <class N, class Tg>
  static Constants<double> constants(const Params&, const ContactPartners& b, const N&, const Tg&) {
    return {b.m12, 1.0 / b.inv_mt};
  }
  template <class T>
  struct Scale {
    T stiffness;  ///< dFn/dh [N/m]
  };
  static Scale<double> scale(const SoftNormal::Eval& e) { return {e.stiffness()}; }
  static double normal(const Params& p, const Constants<double>& k, const Scale<double>& s, double vn) {
    return 2.0 * p.zeta * std::sqrt(k.m12 * s.stiffness) * vn;
  }
  static double tangential(const Params& p, const Constants<double>& k, const Scale<double>&, double kt) {
    return p.tangential_ratio * 2.0 * p.zeta * std::sqrt(k.mt * kt);
  }
};

/// The measured tangential stiffness kt = S_t (a' Δn^b' + c') (Eq. 8) on the Tsuji spring (times
/// the many-body law's normal gain when it has tangential_gain), capped at mu_soft(Δn) Fn; below δ
/// (kt = 0) the contact carries nothing and keeps no spring.
struct SoftTangential {
  template <class T>
  struct Constants {
    T kt_scale;  ///< (R/R0)^n_t
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.kt_scale, Need::friction);
  }
  struct Params {
    const SoftParticleLaws* laws = nullptr;
    bool gain = false;  ///< the many-body law's tangential_gain
  };
  static Params params(const ContactSetting& s) {
    return {s.soft_laws, s.soft_laws && s.soft_laws->many_body && s.soft_laws->many_body->tangential_gain};
  }
  static Constants<double> constants(const Params& p, const ContactPartners& b, const SoftNormal::Constants<double>& normal);
  /// Eq. 8 at the contact's Δn, times the normal gain where the many-body law says so.
  static double stiffness(const Params& p, const Constants<double>& k, const SoftNormal::Eval& e) {
    if (!e.law->tangential) return 0.0;
    const double kt = k.kt_scale * (*e.law->tangential)(e.dn);
    return p.gain ? e.gain * kt : kt;
  }
  static void limit(const Params&, const Constants<double>&, const SoftNormal::Eval& e, double kt, V3<double>& Ft, V3<double>& xi) {
    if (kt > 0.0) tsuji::coulomb_limit(Ft, xi, kt, e.law->mu_at(e.dn) * e.Fn);
    else xi = {0.0, 0.0, 0.0}, Ft = {0.0, 0.0, 0.0};
  }
};

using SoftParticleModel = ContactModel<SoftNormal, SoftDamping, SoftTangential>;
using SoftManyBodyModel = ContactModel<SoftManyBodyNormal, SoftDamping, SoftTangential>;

}  // namespace softpack
