// The contact model: what one contact does, written once for every kind of contact (pairs,
// planes, shells) and every number type, as one value type composed of three sub-laws (the
// pattern of LAMMPS's GranularModel sub-models; each sub-law declares its own per-contact
// constants, as HOOMD-blue's pair potentials declare their param_type):
//
//   normal       Fn from the overlap (Hertz, Eq. 3; the soft-particle's Eq. 7)
//   damping      the viscous terms of the normal and the tangential force
//   tangential   the spring's stiffness and its limit (Tsuji, Eq. 5-6; Eq. 8 and mu_soft)
//
// Pairs, planes and shells (forces/*_contacts.hpp) supply only their geometry: normal, overlap,
// contact-point velocity (ContactGeometry). ContactModel::force() does the rest, in a fixed order:
//
//   spring history (tsuji::advance_spring) -> normal law -> normal damping
//   -> tangential spring -> its limit (Coulomb)
//
// It is a template over the declared effects (contact/effects.hpp: a loop without friction or
// damping holds none of their arithmetic) and over the number type: `double` for one contact,
// simd::Wide for eight at once, with the same bits per lane. A model whose sub-laws are written
// for double only declares kScalarOnly: the loops evaluate its lanes one by one.
//
// Conventions: n is the unit normal pointing from body 2 to body 1, h > 0 the overlap, vc the
// velocity of body 1 relative to body 2 at the contact point (rotation included). The forces
// returned act on body 1; body 2 receives the opposite.
//
// A sub-law is a type with (contact/hertz_normal.hpp, contact/soft_particle_law.hpp show them):
//   Constants<T>                 its per-contact constants (stored per contact, one array each)
//   each_constant(c, f)          f(field, Need) for each of them, in a fixed order
//   Params, params(setting)      what it shares over all contacts, from the scene (ContactSetting)
//   constants(params, partners, ...)  the constants of a new contact
// and the normal one evaluate(params, k, g) -> {Fn, ...}, energy(); the damping one
// scale(eval), normal(), tangential(); the tangential one stiffness(), limit().
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "contact/effects.hpp"
#include "contact/tsuji_tangential.hpp"
#include "core/material.hpp"
#include "core/types.hpp"
#include "simd/vec3.hpp"

namespace softpack {

struct SoftParticleLaws;      // contact/soft_particle_law.hpp
enum class GrainContactRule;  // contact/soft_particle_law.hpp

/// A body's stress tensor from the stress pass (BodyStressModel below) and its radius, for a law
/// with a stress term.
struct BodyStress {
  const SymmetricTensor* S = nullptr;  ///< Σ Fn n ⊗ n over the body's closed contacts [N]; null: none
  double R = 0.0;                      ///< the body's radius [m]
};

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
  /// The two bodies' stress tensors, for a law with a stress term (BodyStressModel; a
  /// scalar-only law, set lane by lane): none for a wall, in the stress pass itself and without it.
  BodyStress stress1{}, stress2{};
};

template <class T>
struct ContactForce {
  V3<T> F;   ///< total force on body 1 [N]
  V3<T> Ft;  ///< its tangential part (for the torques) [N]
  T Fn;      ///< the normal law's force, the Coulomb limit's Fn [N]
};

/// When the loops read a constant: always, or only under the effects that use it.
enum class Need : std::uint8_t { always, damping, friction, friction_damping };

template <Effects Fx>
constexpr bool needed(Need n) {
  switch (n) {
    case Need::damping: return Fx.damping;
    case Need::friction: return Fx.friction;
    case Need::friction_damping: return Fx.friction && Fx.damping;
    case Need::always: break;
  }
  return true;
}

/// What a scene sets that the sub-laws' parameters come from (forces/force_field.cpp fills it).
struct ContactSetting {
  std::vector<Material> materials;
  std::optional<double> restitution;  ///< damping declared: the normal restitution e
  double tangential_ratio = 1.0;      ///< effects.damping.tangential_ratio
  /// The soft-particle model's: the measured laws, how a soft-particle meets a solid sphere,
  /// and whether a contact beyond the laws' measured range stops the run.
  const SoftParticleLaws* soft_laws = nullptr;
  GrainContactRule grain_rule{};
  bool stop_beyond_range = false;
};

/// The two bodies of a new contact, for its constants: body 1 is sphere i, body 2 sphere j or
/// a wall (infinite mass and radius).
struct ContactPartners {
  enum class Kind : std::uint8_t { pair, plane, shell } kind = Kind::pair;
  double R1 = 0.0, R2 = 0.0;  ///< radii [m] (R2: 0 for a wall)
  double R12 = 0.0;           ///< reduced radius: R1 R2 / (R1 + R2), a plane's R1, a shell's concave one
  double m12 = 0.0;           ///< reduced mass [kg] (against a wall: the sphere's)
  double inv_mt = 0.0;        ///< 1/mt of the sliding-rolling mode: the sum of 1/m + r^2/I (1/m without rotation)
  std::size_t materials = 0;  ///< the material pair, a * (number of materials) + b
  bool soft1 = false, soft2 = false;  ///< body 1, body 2 is a soft-particle (effects.soft_particles)
};

/// A model whose normal law reads the state of each body, accumulated over the body's closed
/// contacts by a pass before the forces (the pattern of LAMMPS's EAM and MDR models): its normal
/// sub-law declares kBodyState, body_term(h, its constants) and reads g.body1, g.body2 in evaluate().
template <class Model>
concept BodyStateModel = requires { Model::Normal::kBodyState; } && Model::Normal::kBodyState;

/// A body-state model whose state may be made from each body's closed contacts' caps instead of
/// a sum (the many-body law's union form): its normal sub-law declares kBodyCaps, body_caps(its
/// params) (whether it is), cap_depth_of(h, its constants) (a cap's depth over the body's radius),
/// keeps_cap(its constants, lane, body 1 or 2) (whether that body's state is made from caps at all)
/// and body_state(directions, depths) (the state from a body's caps, its direction from the
/// body's centre towards the contact), which the pass calls for each body of two caps or more.
template <class Model>
concept BodyCapsModel = BodyStateModel<Model> && requires { Model::Normal::kBodyCaps; };

/// A body-state model whose normal law may also read each body's stress tensor (the many-body
/// law's stress term), summed by a second pass once the body states are final: for each closed
/// contact its base force, evaluate() without the tensors, times n ⊗ n added to both bodies'
/// tensors (a grain's is never read). Its normal sub-law declares kBodyStress, body_stress(its
/// params) (whether the law has the term: without it no pass runs) and reads g.stress1,
/// g.stress2 in evaluate(); it is scalar-only (the tensors are set lane by lane).
template <class Model>
concept BodyStressModel = BodyStateModel<Model> && requires { Model::Normal::kBodyStress; };

/// A model written for one contact at a time (double only).
template <class Model>
concept ScalarOnlyModel = requires { Model::Normal::kScalarOnly; } && Model::Normal::kScalarOnly;

template <class NormalLaw, class DampingLaw, class TangentialLaw>
struct ContactModel {
  using Normal = NormalLaw;
  using Damping = DampingLaw;
  using Tangential = TangentialLaw;
  static constexpr const char* name = Normal::name;

  template <class T>
  struct Constants {
    typename Normal::template Constants<T> normal;
    typename Damping::template Constants<T> damping;
    typename Tangential::template Constants<T> tangential;
  };
  struct Params {
    typename Normal::Params normal;
    typename Damping::Params damping;
    typename Tangential::Params tangential;
  };

  static Params params(const ContactSetting& s) { return {Normal::params(s), Damping::params(s), Tangential::params(s)}; }

  /// f(field, Need) for every constant: the normal's, the damping's, the tangential's.
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    Normal::each_constant(c.normal, f);
    Damping::each_constant(c.damping, f);
    Tangential::each_constant(c.tangential, f);
  }
  /// The number of per-contact constants.
  static constexpr std::size_t constant_count() {
    std::size_t n = 0;
    Constants<double> c{};
    each_constant(c, [&](double&, Need) { ++n; });
    return n;
  }

  /// The constants of a new contact (the damping's from the other two's stiffness).
  static Constants<double> constants(const Params& p, const ContactPartners& b) {
    Constants<double> k{};
    k.normal = Normal::constants(p.normal, b);
    k.tangential = Tangential::constants(p.tangential, b, k.normal);
    k.damping = Damping::constants(p.damping, b, k.normal, k.tangential);
    return k;
  }

  /// Force on body 1 of a closed contact. `xi` is the contact's tangential spring before the
  /// step; it is advanced by `dt` (spring history) and shortened when the contact slides.
  template <Effects Fx, class T>
  [[gnu::always_inline]] static ContactForce<T> force(const Params& p, const ContactGeometry<T>& g, const Constants<T>& k, V3<T>& xi,
                                                     double dt) {
    if constexpr (Fx.friction) tsuji::advance_spring(xi, g.n_frame, g.vc_frame, g.n, dt);
    const auto e = Normal::evaluate(p.normal, k.normal, g);
    const T vn = dot(g.vc, g.n);
    T F_normal = e.Fn;
    typename Damping::template Scale<T> s{};
    if constexpr (Fx.damping) {
      s = Damping::scale(e);
      F_normal = F_normal - Damping::normal(p.damping, k.damping, s, vn);
    }
    ContactForce<T> out{F_normal * g.n, {T(0.0), T(0.0), T(0.0)}, e.Fn};
    if constexpr (Fx.friction) {
      const V3<T> vt = g.vc - vn * g.n;
      const T kt = Tangential::stiffness(p.tangential, k.tangential, e);
      const T gamma_t = Fx.damping ? Damping::tangential(p.damping, k.damping, s, kt) : T(0.0);
      out.Ft = -kt * xi - gamma_t * vt;
      Tangential::limit(p.tangential, k.tangential, e, kt, out.Ft, xi);
      out.F = out.F + out.Ft;
    }
    return out;
  }

  // One contact's scalar formulas, for the walk over closed contacts (residuals, watchdog,
  // force between bodies): the same evaluate() as the force, at the contact's overlap g.h, its
  // bodies' states and (a law with a stress term) its normal and its bodies' tensors.
  static double Fn(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g) {
    return Normal::evaluate(p.normal, k.normal, g).Fn;
  }
  static double normal_energy(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g) {
    return Normal::energy(p.normal, k.normal, g.h, g.body1, g.body2);
  }
  /// The tangential stiffness kt [N/m] at the contact's overlap and bodies' states (as the force's).
  static double kt(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g) {
    return Tangential::stiffness(p.tangential, k.tangential, Normal::evaluate(p.normal, k.normal, g));
  }
};

}  // namespace softpack
