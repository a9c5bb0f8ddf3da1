#include "contact/soft_particle_law.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/cpu_features.hpp"
#include "simd/wide.hpp"
#include "softpack_build.hpp"

namespace softpack {

double SoftPowerLaw::integral(double dn) const {
  if (!(dn > delta)) return 0.0;
  const double from = start();
  if (!(dn > from)) return 0.0;
  const auto F = [&](double x) { return a * std::pow(x, b + 1.0) / (b + 1.0) + c * x; };
  return F(dn) - F(from);
}

double SoftSceneLaw::mu_at(double dn) const {
  if (mu.size() == 1 || dn <= mu_dn.front()) return mu.front();
  if (dn >= mu_dn.back()) return mu.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(mu_dn.begin(), mu_dn.end(), dn) - mu_dn.begin());
  const double t = (dn - mu_dn[hi - 1]) / (mu_dn[hi] - mu_dn[hi - 1]);
  return mu[hi - 1] + t * (mu[hi] - mu[hi - 1]);
}

SoftNormal::Constants<double> SoftNormal::constants(const Params& p, const ContactPartners& b) {
  const SoftParticleLaws& laws = *p.laws;
  // R1: the soft-particle's radius (body 1 or body 2), R2 the other body's (0: a wall).
  const double R1 = b.soft1 ? b.R1 : b.R2, R2 = b.soft1 ? b.R2 : b.R1;
  Constants<double> k{};
  const SoftSceneLaw* law = nullptr;
  if (b.kind != ContactPartners::Kind::pair) {
    k.scene = kSoftSolid, law = &*laws.soft_solid, k.R = R1;
  } else if (!(b.soft1 && b.soft2)) {
    k.scene = kSoftSolid, law = &*laws.soft_solid;
    k.R = p.grain_rule == GrainContactRule::wall ? R1 : R1 * R2 / (R1 + R2);
  } else {
    k.scene = kSoftSoft, law = &*laws.soft_soft;
    k.R = R1 == R2 ? R1 : 2.0 * R1 * R2 / (R1 + R2);
  }
  k.F_scale = law->normal_exponent ? std::pow(k.R / laws.R0, *law->normal_exponent) : 1.0;
  return k;
}

SoftTangential::Constants<double> SoftTangential::constants(const Params& p, const ContactPartners&,
                                                            const SoftNormal::Constants<double>& normal) {
  const SoftSceneLaw& law = normal.scene == SoftNormal::kSoftSoft ? *p.laws->soft_soft : *p.laws->soft_solid;
  return {law.tangential_exponent ? std::pow(normal.R / p.laws->R0, *law.tangential_exponent) : 1.0};
}

double cap_depth(double eps) {
  if (!(eps > 0.0)) return 0.0;
  if (!(eps < 1.0)) return 2.0;
  // δ³ − 3δ² + 4ε = 0 with δ = 1 + t: t³ − 3t + 4ε − 2 = 0, whose root in [−1, 1] is
  // t = 2 cos(acos(1 − 2ε) / 3 − 2π/3)
  double d = 1.0 + 2.0 * std::cos(std::acos(1.0 - 2.0 * eps) / 3.0 - 2.0 * std::numbers::pi / 3.0);
  for (int i = 0; i < 3; ++i) {  // Newton on v(δ) − ε, v' = 3δ (2 − δ) / 4
    const double slope = 0.75 * d * (2.0 - d);
    if (!(slope > 0.0)) break;
    d = std::clamp(d - (cap_volume(d) - eps) / slope, 0.0, 2.0);
  }
  return d;
}

namespace {

// The union of caps' integral along the meridians of cap k (cap_union_volume): each meridian's
// piece [lo, hi] of tan θ where cap k is the first cap the ray meets, cap l by cap l for eight
// meridians at once (simd/wide.hpp: each lane gets the bits of the same expressions on one
// double), then its radial integral F(hi) − F(lo), into piece[i].
// ∫ (1 − (h / cos θ)³) sin θ dθ = −cos θ − h³ / (2 cos² θ), written in t = tan θ (cos² θ = 1 / (1 + t²)).
[[gnu::always_inline]] inline void meridian_pieces(const double* cosine, const double* sine, std::size_t M,
                                                   const std::vector<std::array<double, 3>>& m, double h, double t_cap, double* piece) {
  using simd::Wide;
  const double inf = std::numeric_limits<double>::infinity(), h3 = h * h * h;
  const auto F = [h3](Wide t) { return Wide(-1.0) / simd::sqrt(Wide(1.0) + t * t) - Wide(h3) * (Wide(1.0) + t * t) / Wide(2.0); };
  for (std::size_t i = 0; i < M; i += simd::kLanes) {
    const Wide c = simd::load(cosine + i), s = simd::load(sine + i), zero(0.0);
    Wide lo(0.0), hi(t_cap);
    for (const auto& [A, Bc, Bs] : m) {  // where A + B tan θ > 0 the ray is in cap l first
      const Wide B = Wide(Bc) * c + Wide(Bs) * s, q = Wide(-A) / B;
      const Wide to_hi = simd::select(B > zero, A < 0.0 ? q : zero, simd::select(B < zero, Wide(inf), Wide(A > 0.0 ? 0.0 : inf)));
      const Wide to_lo = simd::select(B < zero, A > 0.0 ? q : zero, Wide(-inf));
      hi = simd::select(to_hi < hi, to_hi, hi);
      lo = simd::select(lo < to_lo, to_lo, lo);
    }
    simd::store(piece + i, simd::select(hi > lo, F(hi) - F(lo), zero));
  }
}

// A template, so that a build without AVX-512 loops (softpack_build.hpp) never compiles it.
template <class = void>
[[gnu::target("arch=x86-64-v4"), gnu::flatten]] void meridian_pieces_avx512(const double* cosine, const double* sine, std::size_t M,
                                                                           const std::vector<std::array<double, 3>>& m, double h, double t_cap,
                                                                           double* piece) {
  meridian_pieces(cosine, sine, M, m, h, t_cap, piece);
}

[[gnu::flatten]] void meridian_pieces_portable(const double* cosine, const double* sine, std::size_t M,
                                               const std::vector<std::array<double, 3>>& m, double h, double t_cap, double* piece) {
  meridian_pieces(cosine, sine, M, m, h, t_cap, piece);
}

// On the instruction set chosen at run time (the force loops' choice, forces/compile_loops.hpp).
void meridian_pieces_on(bool avx512, const double* cosine, const double* sine, std::size_t M, const std::vector<std::array<double, 3>>& m, double h,
                        double t_cap, double* piece) {
  if constexpr (build::kAvx512Loops)
    if (avx512) return meridian_pieces_avx512(cosine, sine, M, m, h, t_cap, piece);
  meridian_pieces_portable(cosine, sine, M, m, h, t_cap, piece);
}

}  // namespace

double cap_union_volume(const std::vector<Vec3>& n, const std::vector<double>& depth, int meridians) {
  // Kept from call to call (the engine calls this for every soft-particle of two caps or more, every step).
  thread_local std::vector<double> h, s, cosine, sine, piece;
  if (!(meridians > 0) || meridians % simd::kLanes != 0)
    throw std::invalid_argument("cap_union_volume: the meridians must be a positive multiple of " + std::to_string(simd::kLanes) + " (got " +
                                std::to_string(meridians) + ")");
  thread_local std::vector<std::array<double, 3>> m;  // A, and B = Bc cos φ + Bs sin φ, of each cap that meets cap k
  const std::size_t caps = n.size();
  h.resize(caps), s.resize(caps);
  for (std::size_t k = 0; k < caps; ++k) {
    h[k] = 1.0 - std::clamp(depth[k], 0.0, 1.0 - 1e-9);  // the plane's distance 1 − δ: cos of the cap's half-angle
    s[k] = std::sqrt(1.0 - h[k] * h[k]);                  // its sine
  }
  if (cosine.size() != static_cast<std::size_t>(meridians)) {
    cosine.resize(static_cast<std::size_t>(meridians)), sine.resize(static_cast<std::size_t>(meridians));
    piece.resize(static_cast<std::size_t>(meridians));
    for (int i = 0; i < meridians; ++i) cosine[static_cast<std::size_t>(i)] = std::cos(2.0 * std::numbers::pi * i / meridians),
                                        sine[static_cast<std::size_t>(i)] = std::sin(2.0 * std::numbers::pi * i / meridians);
  }
  const bool avx512 = build::kAvx512Loops && cpu::vector_isa() == cpu::VectorIsa::avx512;
  double total = 0.0;
  for (std::size_t k = 0; k < caps; ++k) {
    if (!(depth[k] > 0.0)) continue;
    const double whole = (-h[k] - h[k] / 2.0) - (-1.0 - h[k] * h[k] * h[k] / 2.0);  // the meridian over the whole cap
    const Vec3 e1 = n[k].unitOrthogonal(), e2 = n[k].cross(e1);
    m.clear();  // where u·(h_k n_l − h_l n_k) > 0 the ray is in cap l first (the caps meet: their half-angles add to more than the angle between them)
    for (std::size_t l = 0; l < caps; ++l)
      if (l != k && depth[l] > 0.0 && n[k].dot(n[l]) > h[k] * h[l] - s[k] * s[l]) {
        const Vec3 ml = h[k] * n[l] - h[l] * n[k];
        m.push_back({ml.dot(n[k]), ml.dot(e1), ml.dot(e2)});
      }
    if (m.empty()) {
      total += 0.5 * whole;
      continue;
    }
    const auto M = static_cast<std::size_t>(meridians);
    meridian_pieces_on(avx512, cosine.data(), sine.data(), M, m, h[k], s[k] / h[k], piece.data());
    double sum = 0.0;
    for (std::size_t i = 0; i < M; ++i) sum += piece[i];  // in meridian order
    total += 0.5 * sum / meridians;
  }
  return total;
}

SoftManyBodyNormal::Constants<double> SoftManyBodyNormal::constants(const Params& p, const ContactPartners& b) {
  Constants<double> k{};
  static_cast<SoftNormal::Constants<double>&>(k) = SoftNormal::constants(p, b);
  k.soft = b.soft1 && b.soft2 ? kBoth : b.soft1 ? kBody1 : kBody2;
  const ManyBodyLaw& m = *p.laws->many_body;
  k.beta = m.beta, k.scale = 1.0;
  if (k.soft == kBoth) {
    k.beta = m.soft_beta.value_or(m.beta);
  } else if (b.kind == ContactPartners::Kind::pair) {  // a solid sphere of radius r against the soft-particle's R
    const double x = (b.soft1 ? b.R2 : b.R1) / (b.soft1 ? b.R1 : b.R2);
    k.beta = m.grain_beta.value_or(m.beta);
    if (m.grain_exponent != 0.0) k.scale = std::pow(x / (1.0 + x), m.grain_exponent);
  }
  return k;
}

double SoftManyBodyNormal::others(const Constants<double>& k, double v, double s1, double s2) {
  if (k.soft == kBoth) return 0.5 * ((s1 - v) + (s2 - v));
  return (k.soft == kBody1 ? s1 : s2) - v;
}

double SoftManyBodyNormal::force(const Params& p, const Constants<double>& k, double dn, double others) {
  return many_body_force(p.law(k.scene).normal, k.scale * k.F_scale, dn, others, k.beta);
}

double SoftManyBodyNormal::stress_on(ManyBodyLaw::SoftStress::Form form, const SymmetricTensor& S, double R, const V3<double>& n, double Fn) {
  using Form = ManyBodyLaw::SoftStress::Form;
  const double trace = S[0] + S[1] + S[2];
  const double nSn = S[0] * n.x * n.x + S[1] * n.y * n.y + S[2] * n.z * n.z + 2.0 * (S[3] * n.x * n.y + S[4] * n.x * n.z + S[5] * n.y * n.z);
  const double surface = 4.0 * std::numbers::pi * R * R;
  const double p = form == Form::mean ? (trace - Fn) / surface : form == Form::normal ? 3.0 * (nSn - Fn) / surface : 3.0 * (trace - nSn) / (2.0 * surface);
  return std::max(p, 0.0);
}

SoftNormal::Eval SoftManyBodyNormal::evaluate(const Params& p, const Constants<double>& k, const ContactGeometry<double>& g) {
  Eval e = SoftNormal::evaluate(p, k, g);
  const double pairwise = e.Fn;  // Eq. 7: the gain is over it (a grain's g included)
  e.Fn = force(p, k, e.dn, others(k, cap_volume(e.dn), g.body1, g.body2));  // Fn_base
  const auto& stress = p.laws->many_body->soft_stress;
  if (stress && k.soft == kBoth && g.stress1.S && g.stress2.S) {
    const double p1 = stress_on(stress->form, *g.stress1.S, g.stress1.R, g.n, e.Fn), p2 = stress_on(stress->form, *g.stress2.S, g.stress2.R, g.n, e.Fn);
    e.Fn += stress->kappa * std::numbers::pi * k.R * k.R * cap_area(e.dn) * 0.5 * (p1 + p2);
  }
  e.gain = pairwise > 0.0 ? e.Fn / pairwise : 1.0;
  return e;
}

double SoftManyBodyNormal::energy(const Params& p, const Constants<double>& k, double h, double s1, double s2) {
  if (!(h > 0.0)) return 0.0;
  const double dn = h / k.R, rest = others(k, cap_volume(dn), s1, s2);
  const SoftPowerLaw& X = p.law(k.scene).normal;
  if (!(rest > 0.0)) return k.scale * k.F_scale * k.R * X.integral(dn);  // alone: Eq. 7's integral, as the pairwise model's
  // The force is 0 until δ* = cap_depth(v(Δn) + β E_others) reaches where Eq. 7 starts: Simpson's
  // rule from there, where the integrand is smooth (from 0 it would straddle the onset's kink),
  // its first node the force just above the onset (δ* = start exactly; cap_depth's round trip
  // could land a few units of the last place below it, where Eq. 7 is 0).
  const double start = X.start(), from = cap_depth(cap_volume(start) - k.beta * rest);
  if (!(dn > from)) return 0.0;
  constexpr int n = kEnergyIntervals;
  const double step = (dn - from) / n;
  double sum = from > 0.0 ? k.scale * k.F_scale * X(start) * cap_area(from) / cap_area(start) : 0.0;
  for (int i = 1; i <= n; ++i) sum += (i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * force(p, k, from + step * i, rest);
  return sum * (step * k.R) / 3.0;
}

double linear_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

}  // namespace softpack
