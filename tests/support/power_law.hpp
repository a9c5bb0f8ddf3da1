// Eq. 7 as a fit result with its onset, for tests that make a synthetic probe.
#pragma once
#include <cmath>

#include "analysis/power_fit.hpp"

namespace softpack::testing {

/// a Δn^b + c, its onset δ = (−c/a)^(1/b).
inline fit::PowerLawFit eq7_fit(double a, double b, double c) {
  fit::PowerLawFit f;
  f.a = a, f.b = b, f.c = c, f.delta = std::pow(-c / a, 1.0 / b);
  return f;
}

}  // namespace softpack::testing
