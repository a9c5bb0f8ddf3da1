#include "contact/soft_particle_law.hpp"

#include <algorithm>
#include <numbers>

#include "contact/tsuji_tangential.hpp"

namespace softpack {

double SoftPowerLaw::integral(double dn) const {
  if (!(dn > delta)) return 0.0;
  // Where a Δn^b + c > 0 starts: δ for c = -a δ^b, later when a fit's c is more negative.
  const double start = c < 0.0 ? std::max(delta, std::pow(-c / a, 1.0 / b)) : delta;
  if (!(dn > start)) return 0.0;
  const auto F = [&](double x) { return a * std::pow(x, b + 1.0) / (b + 1.0) + c * x; };
  return F(dn) - F(start);
}

double SoftSceneLaw::mu_at(double dn) const {
  if (mu.size() == 1 || dn <= mu_dn.front()) return mu.front();
  if (dn >= mu_dn.back()) return mu.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(mu_dn.begin(), mu_dn.end(), dn) - mu_dn.begin());
  const double t = (dn - mu_dn[hi - 1]) / (mu_dn[hi] - mu_dn[hi - 1]);
  return mu[hi - 1] + t * (mu[hi] - mu[hi - 1]);
}

SoftContactConstants soft_contact_constants(const SoftParticleLaws& laws, SoftContactKind kind, GrainContactRule grain_rule,
                                            double R1, double R2, double m12, double mt) {
  SoftContactConstants k;
  k.m12 = m12, k.mt = mt;
  switch (kind) {
    case SoftContactKind::wall: k.law = &*laws.soft_solid, k.R = R1; break;
    case SoftContactKind::grain:
      k.law = &*laws.soft_solid;
      k.R = grain_rule == GrainContactRule::wall ? R1 : R1 * R2 / (R1 + R2);
      break;
    case SoftContactKind::soft: k.law = &*laws.soft_soft, k.R = R1 == R2 ? R1 : 2.0 * R1 * R2 / (R1 + R2); break;
  }
  const double ratio = k.R / laws.R0;
  k.F_scale = k.law->normal_exponent ? std::pow(ratio, *k.law->normal_exponent) : 1.0;
  k.kt_scale = k.law->tangential_exponent ? std::pow(ratio, *k.law->tangential_exponent) : 1.0;
  return k;
}

double linear_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

double soft_Fn(const SoftContactConstants& k, double h) { return k.F_scale * k.law->normal(h / k.R); }

double soft_kt(const SoftContactConstants& k, double h) { return k.law->tangential ? k.kt_scale * (*k.law->tangential)(h / k.R) : 0.0; }

ContactForce<double> soft_contact_force(const ContactGeometry<double>& g, const SoftContactConstants& k, const SoftEffects& fx,
                                        V3<double>& xi, double dt, double& dn) {
  if (fx.friction) tsuji::advance_spring(xi, g.n_frame, g.vc_frame, g.n, dt);
  dn = g.h / k.R;
  const SoftSceneLaw& law = *k.law;
  const double Fn = k.F_scale * law.normal(dn);  // Eq. 7 at R
  const double vn = dot(g.vc, g.n);
  double F_normal = Fn;
  if (fx.damping) {
    const double k_local = k.F_scale * law.normal.slope(dn) / k.R;  // dFn/dh [N/m]
    F_normal -= 2.0 * fx.zeta * std::sqrt(k.m12 * k_local) * vn;
  }
  ContactForce<double> out{F_normal * g.n, {0.0, 0.0, 0.0}, Fn};
  if (fx.friction) {
    const double kt = k.kt_scale * (*law.tangential)(dn);  // Eq. 8 at R [N/m]
    V3<double> Ft = -kt * xi;
    if (fx.damping) Ft = Ft - (fx.tangential_ratio * 2.0 * fx.zeta * std::sqrt(k.mt * kt)) * (g.vc - vn * g.n);
    if (kt > 0.0) tsuji::coulomb_limit(Ft, xi, kt, law.mu_at(dn) * Fn);
    else xi = {0.0, 0.0, 0.0}, Ft = {0.0, 0.0, 0.0};  // below δ the contact carries nothing
    out.Ft = Ft;
    out.F = out.F + Ft;
  }
  return out;
}

double soft_contact_energy(const SoftContactConstants& k, double h, const Vec3* xi) {
  double E = k.F_scale * k.R * k.law->normal.integral(h / k.R);
  if (xi) E += tsuji::energy(soft_kt(k, h), v3(*xi));
  return E;
}

}  // namespace softpack
