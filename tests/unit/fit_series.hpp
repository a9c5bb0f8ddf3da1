// Eq. 7 series for the fit tests (test_fit.cpp, test_fit_options.cpp): the paper's laws,
// sampled on the sweep's grid with the seed averages' kind of standard errors and noise.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/random.hpp"

namespace softpack::fit_test {

/// A standard normal variate by Box–Muller (the cosine branch) from two uniforms.
inline double gaussian(Random& rng) {
  const double u1 = 1.0 - rng.uniform();  // (0, 1]
  const double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

struct Law {
  const char* name;
  double a, b, c;
  double delta() const { return std::pow(-c / a, 1.0 / b); }
  double operator()(double x) const { return x < delta() ? 0.0 : a * std::pow(x, b) + c; }
};

inline const Law kSoftSolid{"soft-solid", 73.669, 2.799, -0.035};
inline const Law kSoftSoft{"soft-soft", 28.512, 5.003, -0.002};
inline const Law kSteep{"steep onset", 10.0, 1.5, -0.5};

struct Series {
  std::vector<double> x, y, e;
};

/// Eq. 7 on Δn = 0, 0.0125, …, 0.5: zero below δ; above, σ = 2% of F plus 0.1% of F(0.5),
/// and Gaussian noise of that σ when `rng` is given.
inline Series normal_series(const Law& law, Random* rng) {
  Series s;
  const double floor = 1e-3 * law(0.5);
  for (int k = 0; k <= 40; ++k) {
    const double x = 0.0125 * k, f = law(x);
    const double sigma = f > 0.0 ? 0.02 * f + floor : 0.0;
    s.x.push_back(x);
    s.y.push_back(f > 0.0 && rng ? f + sigma * gaussian(*rng) : f);
    s.e.push_back(sigma);
  }
  return s;
}

inline void expect_within(double fitted, double error, double truth, double k, const std::string& what) {
  EXPECT_LE(std::abs(fitted - truth), k * error) << what << ": fitted " << fitted << " +- " << error << ", true " << truth;
}

}  // namespace softpack::fit_test
