// The damping coefficient zeta(e) (Tsuji's alpha) of the Tsuji damping, from the scaled impact equation (contact/viscous_damping.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/viscous_damping.hpp"

namespace softpack {
namespace {

TEST(DampingAlpha, UndampedImpactIsElastic) {
  EXPECT_NEAR(damping::restitution_from_zeta(0.0), 1.0, 1e-9);
  EXPECT_EQ(damping::zeta_from_restitution(1.0), 0.0);
}

TEST(DampingAlpha, InverseReproducesRestitution) {
  for (double e : {0.05, 0.3, 0.5, 0.8, 0.95, 0.999}) {
    const double zeta = damping::zeta_from_restitution(e);
    EXPECT_GT(zeta, 0.0);
    EXPECT_NEAR(damping::restitution_from_zeta(zeta), e, 1e-9) << "e = " << e;
  }
}

TEST(DampingAlpha, RestitutionDecreasesWithAlpha) {
  double previous = 1.0;
  // Beyond zeta ~ 2.2 the spheres stick (e = 0).
  for (double zeta = 0.1; zeta < 2.0; zeta += 0.1) {
    const double e = damping::restitution_from_zeta(zeta);
    EXPECT_LT(e, previous);
    previous = e;
  }
}

// Tsuji et al. (1992) tabulated zeta(e); LAMMPS carries a polynomial fit of that table. Our
// exact inversion is sqrt(2) times the fit, to the fit's accuracy of a few percent: Tsuji's
// table corresponds to sqrt(m kn) with m the mass of one of two equal spheres, i.e. twice the
// reduced mass m12 that our (and LAMMPS's) formula uses. Consequence, documented in
// docs/physics.md: LAMMPS's `damping tsuji` with e = 0.5 gives a restitution near 0.62.
TEST(DampingAlpha, IsSqrt2TimesTsujisPolynomialFit) {
  const auto tsuji_fit = [](double e) {
    return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
           18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
  };
  for (double e : {0.3, 0.5, 0.7, 0.9}) {
    const double zeta = damping::zeta_from_restitution(e);
    EXPECT_NEAR(zeta, std::sqrt(2.0) * tsuji_fit(e), 0.01 * zeta) << "e = " << e;
  }
}

TEST(DampingAlpha, RejectsRestitutionOutsideRange) {
  EXPECT_THROW(damping::zeta_from_restitution(0.0), std::invalid_argument);
  EXPECT_THROW(damping::zeta_from_restitution(1.5), std::invalid_argument);
}

}  // namespace
}  // namespace softpack
