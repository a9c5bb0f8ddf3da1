// Contact constants of two materials: paper Eq. 4 and Eq. 6.
#include <gtest/gtest.h>

#include "core/material.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

TEST(Material, HertzDIsEquation4) {
  const Material a = testing::paper_grain(), b = testing::stiff_grain();
  EXPECT_DOUBLE_EQ(hertz_D(a, b), 0.75 * ((1 - a.nu * a.nu) / a.E + (1 - b.nu * b.nu) / b.E));
  EXPECT_DOUBLE_EQ(hertz_D(a, b), hertz_D(b, a));
}

TEST(Material, TsujiDtReducesToEquation6ForOneMaterial) {
  const Material a = testing::paper_grain();
  const double eq6 = 2 * a.E / ((2 - a.nu) * (1 + a.nu));
  EXPECT_NEAR(tsuji_Dt(a, a), eq6, 1e-12 * eq6);
}

TEST(Material, TsujiDtOfTwoMaterialsIsMindlinsEffectiveShearModulus) {
  const Material a = testing::paper_grain(), b = testing::stiff_grain();
  const double Ga = a.E / (2 * (1 + a.nu)), Gb = b.E / (2 * (1 + b.nu));
  const double expected = 8.0 / ((2 - a.nu) / Ga + (2 - b.nu) / Gb);
  EXPECT_NEAR(tsuji_Dt(a, b), expected, 1e-12 * expected);
  EXPECT_DOUBLE_EQ(tsuji_Dt(a, b), tsuji_Dt(b, a));
}

TEST(Material, FrictionCoefficientIsGeometricMean) {
  const Material a = testing::paper_grain(), b = testing::stiff_grain();
  EXPECT_DOUBLE_EQ(contact_mu(a, a), a.mu);
  EXPECT_DOUBLE_EQ(contact_mu(a, b), std::sqrt(a.mu * b.mu));
}

}  // namespace
}  // namespace softpack
