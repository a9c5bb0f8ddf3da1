#include "packing/statistics.hpp"

#include "core/types.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softpack {

double volume_inside_ball(double d, double a, double R) {
  constexpr double k = 4.0 / 3.0 * std::numbers::pi;
  if (d + a <= R) return k * a * a * a;
  if (d >= R + a) return 0.0;
  if (d + R <= a) return k * R * R * R;
  // Lens of two spheres of radii a and R whose centres are d apart.
  const double t = R + a - d;
  return std::numbers::pi * t * t * (d * d + 2.0 * d * a - 3.0 * a * a + 2.0 * d * R + 6.0 * a * R - 3.0 * R * R) /
         (12.0 * d);
}

RadialProfile radial_profile(std::span<const Vec3> centres, std::span<const double> radii, double Rs, int bins) {
  RadialProfile p;
  const double dr = Rs / bins;
  std::vector<double> inside(static_cast<std::size_t>(bins) + 1, 0.0);  // solid volume within edge k
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double d = centres[i].norm(), a = radii[i];
    // Only the edges the sphere straddles change; beyond them it is entirely in or out.
    const int k0 = std::max(0, static_cast<int>(std::floor((d - a) / dr)));
    const int k1 = std::min(bins, static_cast<int>(std::ceil((d + a) / dr)));
    for (int k = k0; k <= k1; ++k) inside[k] += volume_inside_ball(d, a, k * dr);
    const double full = 4.0 / 3.0 * std::numbers::pi * a * a * a;
    for (int k = k1 + 1; k <= bins; ++k) inside[k] += full;
  }
  for (int k = 0; k < bins; ++k) {
    const double lo = k * dr, hi = (k + 1) * dr;
    p.r_inner.push_back(lo);
    p.r_outer.push_back(hi);
    p.solid_fraction.push_back((inside[k + 1] - inside[k]) / (4.0 / 3.0 * std::numbers::pi * (hi * hi * hi - lo * lo * lo)));
  }
  return p;
}

PackingStatistics packing_statistics(std::span<const Vec3> centres, std::span<const double> radii, double Rs,
                                     double r_max, int bins) {
  PackingStatistics s;
  double volume = 0.0;
  s.min_shell_gap = Rs;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    volume += radii[i] * radii[i] * radii[i];
    s.min_shell_gap = std::min(s.min_shell_gap, Rs - centres[i].norm() - radii[i]);
  }
  s.solid_fraction = volume / (Rs * Rs * Rs);
  s.profile = radial_profile(centres, radii, Rs, bins);
  // Bulk: the bins entirely within Rs - 2 r_max; depletion: the missing solid beyond, as a length.
  const double edge = Rs - 2.0 * r_max;
  double bulk_volume = 0.0, bulk_solid = 0.0;
  for (int k = 0; k < bins; ++k) {
    const double lo = s.profile.r_inner[k], hi = s.profile.r_outer[k];
    if (hi > edge) continue;
    const double v = hi * hi * hi - lo * lo * lo;
    bulk_volume += v;
    bulk_solid += v * s.profile.solid_fraction[k];
  }
  s.bulk_fraction = bulk_volume > 0.0 ? bulk_solid / bulk_volume : s.solid_fraction;
  for (int k = 0; k < bins; ++k) {
    const double lo = s.profile.r_inner[k], hi = s.profile.r_outer[k];
    if (hi <= edge) continue;
    s.depletion_length += (1.0 - s.profile.solid_fraction[k] / s.bulk_fraction) * (hi - std::max(lo, edge));
  }
  // A power law's exponent needs radii of different sizes: a packing of one size (an imported one
  // may be) has none, NaN, with r_min = r_max (it was an internal error, issue 28).
  if (radii.size() >= 2) {
    const auto [lo, hi] = std::minmax_element(radii.begin(), radii.end());
    s.exponent = *hi > *lo ? power_law::fit(radii) : power_law::Fit{kNaN, kNaN, *lo, *hi};
  }
  return s;
}

}  // namespace softpack
