// The solid grains' contact model (contact/contact_model.hpp), the paper's: a normal law with one
// stiffness per contact from the materials (Hertz, Eq. 3-4: contact/hertz_normal.hpp), Tsuji's
// viscous damping (contact/viscous_damping.hpp) and Tsuji's tangential spring (Eq. 5-6,
// contact/tsuji_tangential.hpp):
//
//   TsujiModel<Law> = ContactModel<MaterialNormal<Law>, ViscousDamping<Law>, TsujiSpring>
//
// `Law` is a normal law written as contact/hertz_normal.hpp writes Hertz's: stiffness(R12, D),
// force(kn, h, sqrt_h), energy(kn, h), damping_scale(sqrt_h), damping_coefficient(e) (and, for
// a body state, kBodyState, body_term(h) and force/energy with the two bodies' states).
// docs/architecture.md, "Adding a normal law", says how one is added.
#pragma once
#include <cmath>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/tsuji_tangential.hpp"
#include "contact/viscous_damping.hpp"
#include "core/material.hpp"
#include "simd/wide.hpp"

namespace softpack {

/// A normal law that declares a body state (contact/hertz_normal.hpp).
template <class Law>
concept LawWithBodyState = requires { requires Law::kBodyState; };

namespace detail {
/// f(a, b) for every ordered pair of the setting's materials, index a * M + b.
template <class F>
std::vector<double> material_table(const ContactSetting& s, F&& f) {
  const std::size_t M = s.materials.size();
  std::vector<double> t(M * M);
  for (std::size_t a = 0; a < M; ++a)
    for (std::size_t b = 0; b < M; ++b) t[a * M + b] = f(s.materials[a], s.materials[b]);
  return t;
}
}  // namespace detail

/// The normal sub-law of a law whose per-contact constant is its stiffness kn = Law::stiffness(R12, D),
/// D of the two materials (Eq. 4).
template <class Law>
struct MaterialNormal {
  static constexpr const char* name = Law::name;
  static constexpr bool kBodyState = LawWithBodyState<Law>;

  template <class T>
  struct Constants {
    T kn;  ///< Hertz: sqrt(R12) / D, Fn = kn h^(3/2)
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.kn, Need::always);
  }
  struct Params {
    std::vector<double> D;  ///< Eq. 4, per material pair [1/Pa]
  };
  static Params params(const ContactSetting& s) { return {detail::material_table(s, hertz_D)}; }
  static Constants<double> constants(const Params& p, const ContactPartners& b) { return {Law::stiffness(b.R12, p.D[b.materials])}; }

  /// Fn, and sqrt(h), which the damping and the tangential stiffness share.
  template <class T>
  struct Eval {
    T Fn, sqrt_h;
  };
  template <class T>
  [[gnu::always_inline]] static Eval<T> evaluate(const Params&, const Constants<T>& k, const ContactGeometry<T>& g) {
    const T sqrt_h = simd::sqrt(g.h);
    if constexpr (kBodyState) return {Law::force(k.kn, g.h, sqrt_h, g.body1, g.body2), sqrt_h};
    else return {Law::force(k.kn, g.h, sqrt_h), sqrt_h};
  }
  static double energy(const Params&, const Constants<double>& k, double h, [[maybe_unused]] double s1, [[maybe_unused]] double s2) {
    if constexpr (kBodyState) return Law::energy(k.kn, h, s1, s2);
    else return Law::energy(k.kn, h);
  }
  template <class T>
  [[gnu::always_inline]] static T body_term(const T& h, const Constants<T>&) {
    return Law::body_term(h);
  }
};

/// Tsuji's viscous damping (contact/viscous_damping.hpp): gamma_n = gamma0 g(h), gamma_t =
/// gamma_t0 g(h), with the law's g(h) (Hertz: h^(1/4)) and the zeta that gives the restitution.
template <class Law>
struct ViscousDamping {
  template <class T>
  struct Constants {
    T gamma0;    ///< zeta sqrt(m12 kn)
    T gamma_t0;  ///< ratio_t zeta sqrt(mt kt0)
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.gamma0, Need::damping);
    f(c.gamma_t0, Need::friction_damping);
  }
  struct Params {
    double zeta = 0.0, tangential_ratio = 1.0;
  };
  static Params params(const ContactSetting& s) {
    return {s.restitution ? Law::damping_coefficient(*s.restitution) : 0.0, s.tangential_ratio};
  }
  template <class N, class Tg>
  static Constants<double> constants(const Params& p, const ContactPartners& b, const N& normal, const Tg& tangential) {
    return {damping::gamma_factor(p.zeta, b.m12, normal.kn), p.tangential_ratio * damping::gamma_factor(p.zeta, 1.0 / b.inv_mt, tangential.kt0)};
  }
  template <class T>
  struct Scale {
    T g_h;  ///< g(h)
  };
  template <class Eval>
  [[gnu::always_inline]] static auto scale(const Eval& e) {
    return Scale<decltype(e.Fn)>{Law::damping_scale(e.sqrt_h)};
  }
  /// gamma_n vn [N].
  template <class T>
  [[gnu::always_inline]] static T normal(const Params&, const Constants<T>& k, const Scale<T>& s, const T& vn) {
    return k.gamma0 * s.g_h * vn;
  }
  /// gamma_t [kg/s].
  template <class T>
  [[gnu::always_inline]] static T tangential(const Params&, const Constants<T>& k, const Scale<T>& s, const T&) {
    return k.gamma_t0 * s.g_h;
  }
};

/// Tsuji's tangential spring (Eq. 5-6): kt = kt0 sqrt(h), kt0 = Dt sqrt(R12), |Ft| <= mu Fn.
struct TsujiSpring {
  template <class T>
  struct Constants {
    T kt0;  ///< Dt sqrt(R12), kt = kt0 sqrt(h)  (Eq. 5)
    T mu;   ///< Coulomb coefficient
  };
  template <class C, class F>
  static constexpr void each_constant(C& c, F&& f) {
    f(c.kt0, Need::friction);
    f(c.mu, Need::friction);
  }
  struct Params {
    std::vector<double> Dt, mu;  ///< Eq. 6 [Pa] and the Coulomb coefficient, per material pair
  };
  static Params params(const ContactSetting& s) { return {detail::material_table(s, tsuji_Dt), detail::material_table(s, contact_mu)}; }
  template <class N>
  static Constants<double> constants(const Params& p, const ContactPartners& b, const N&) {
    return {tsuji::stiffness_factor(b.R12, p.Dt[b.materials]), p.mu[b.materials]};
  }
  /// Eq. 5: kt = sqrt(R12 h) Dt [N/m].
  template <class T, class Eval>
  [[gnu::always_inline]] static T stiffness(const Params&, const Constants<T>& k, const Eval& e) {
    return k.kt0 * e.sqrt_h;
  }
  /// Eq. 5's cap |Ft| <= mu Fn.
  template <class T, class Eval>
  [[gnu::always_inline]] static void limit(const Params&, const Constants<T>& k, const Eval& e, const T& kt, V3<T>& Ft, V3<T>& xi) {
    tsuji::coulomb_limit(Ft, xi, kt, k.mu * e.Fn);
  }
};

template <class Law>
using TsujiModel = ContactModel<MaterialNormal<Law>, ViscousDamping<Law>, TsujiSpring>;

}  // namespace softpack
