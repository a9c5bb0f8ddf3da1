#include "core/material.hpp"

#include <cmath>

namespace softpack {

double hertz_D(const Material& a, const Material& b) {
  return 0.75 * ((1.0 - a.nu * a.nu) / a.E + (1.0 - b.nu * b.nu) / b.E);
}

double shear_modulus(const Material& m) { return m.E / (2.0 * (1.0 + m.nu)); }

double tsuji_Dt(const Material& a, const Material& b) {
  const double inv_G_star = (2.0 - a.nu) / shear_modulus(a) + (2.0 - b.nu) / shear_modulus(b);
  return 8.0 / inv_G_star;
}

double contact_mu(const Material& a, const Material& b) { return std::sqrt(a.mu * b.mu); }

}  // namespace softpack
