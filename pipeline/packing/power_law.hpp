// The truncated power law of the sizes, paper Eq. 1:
//
//   P(r) = a r^(-b),   r_min < r < r_max,   a = (b - 1) / (r_min^(1-b) - r_max^(1-b))   (b != 1)
//
// sampled by inverting its cumulative distribution, and fitted by maximum likelihood.
#pragma once
#include <span>

#include "core/random.hpp"

namespace softpack::power_law {

struct Law {
  double r_min = 0.0, r_max = 0.0;  ///< [m]
  double b = 0.0;                   ///< exponent, b > 1
};

/// Cumulative distribution F(r) = (r_min^(1-b) - r^(1-b)) / (r_min^(1-b) - r_max^(1-b)).
double cdf(const Law& law, double r);

/// Inverse of the cumulative distribution at u in [0, 1).
double quantile(const Law& law, double u);

/// One radius drawn by inverse transform sampling.
inline double sample(const Law& law, Random& rng) { return quantile(law, rng.uniform()); }

/// Mean of r^3 (for the expected volume of a list of spheres).
double mean_cube(const Law& law);

struct Fit {
  double b = 0.0;        ///< maximum-likelihood exponent
  double b_error = 0.0;  ///< standard error from the Fisher information, 1/sqrt(-l''(b))
  double r_min = 0.0, r_max = 0.0;  ///< the truncation used: the sample's smallest and largest
};

/// Maximum-likelihood exponent of a truncated power law on [min r, max r] of the sample.
Fit fit(std::span<const double> radii);

}  // namespace softpack::power_law
