#include "contact/soft_particle_law.hpp"

#include <algorithm>
#include <numbers>

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

double linear_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

}  // namespace softpack
