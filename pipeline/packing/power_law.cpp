#include "packing/power_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softpack::power_law {

double cdf(const Law& law, double r) {
  const double e = 1.0 - law.b;
  const double lo = std::pow(law.r_min, e), hi = std::pow(law.r_max, e);
  return std::clamp((lo - std::pow(r, e)) / (lo - hi), 0.0, 1.0);
}

double quantile(const Law& law, double u) {
  const double e = 1.0 - law.b;
  const double lo = std::pow(law.r_min, e), hi = std::pow(law.r_max, e);
  return std::pow(lo - u * (lo - hi), 1.0 / e);
}

double mean_cube(const Law& law) {
  // integral of r^3 a r^-b dr over [r_min, r_max], a = (b - 1)/(r_min^(1-b) - r_max^(1-b)).
  const double a = (law.b - 1.0) / (std::pow(law.r_min, 1.0 - law.b) - std::pow(law.r_max, 1.0 - law.b));
  const double e = 4.0 - law.b;
  if (std::abs(e) < 1e-12) return a * std::log(law.r_max / law.r_min);
  return a * (std::pow(law.r_max, e) - std::pow(law.r_min, e)) / e;
}

namespace {

// Log-likelihood per sphere of exponent b on [lo, hi] given the mean of log r.
double log_likelihood(double b, double lo, double hi, double mean_log_r) {
  const double e = 1.0 - b;
  // log a = log(b - 1) - log(lo^(1-b) - hi^(1-b)); written with lo factored out for accuracy.
  const double log_norm = e * std::log(lo) + std::log1p(-std::pow(hi / lo, e));
  return std::log(b - 1.0) - log_norm - b * mean_log_r;
}

}  // namespace

Fit fit(std::span<const double> radii) {
  if (radii.size() < 2) throw std::invalid_argument("power_law::fit needs at least two radii");
  const auto [lo_it, hi_it] = std::minmax_element(radii.begin(), radii.end());
  const double lo = *lo_it, hi = *hi_it;
  if (!(hi > lo)) throw std::invalid_argument("power_law::fit needs radii of different sizes");
  double mean_log_r = 0.0;
  for (double r : radii) mean_log_r += std::log(r);
  mean_log_r /= static_cast<double>(radii.size());
  // The log-likelihood is concave in b: golden-section search on (1, 20].
  const auto l = [&](double b) { return log_likelihood(b, lo, hi, mean_log_r); };
  double a = 1.0 + 1e-9, c = 20.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = c - g * (c - a), x2 = a + g * (c - a);
  double f1 = l(x1), f2 = l(x2);
  while (c - a > 1e-12 * c) {
    if (f1 < f2) {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (c - a), f2 = l(x2);
    } else {
      c = x2, x2 = x1, f2 = f1, x1 = c - g * (c - a), f1 = l(x1);
    }
  }
  Fit out;
  out.b = 0.5 * (a + c);
  out.r_min = lo;
  out.r_max = hi;
  // Fisher information: N times minus the second derivative of the per-sphere log-likelihood.
  const double db = 1e-4 * out.b;
  const double second = (l(out.b + db) - 2.0 * l(out.b) + l(out.b - db)) / (db * db);
  out.b_error = 1.0 / std::sqrt(-second * static_cast<double>(radii.size()));
  return out;
}

}  // namespace softpack::power_law
