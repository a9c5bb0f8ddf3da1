// The radius study's scaling fit (report/radius_report.hpp, common_exponent): a power law's
// exponent shared by several groups (the forces at several delta_n), each with its own prefactor.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "report/radius_report.hpp"

namespace softpack {
namespace {

// Synthetic laws X_j(R) = A_j (R / R0)^n at four radii and three delta_n: exact values give n
// exactly (to rounding) whatever the prefactors and the errors.
TEST(RadiusScaling, RecoversTheExponentOfExactPowerLaws) {
  for (const double n : {2.0, 2.37, 3.0, 1.0}) {
    std::vector<std::vector<double>> x(3), y(3), e(3);
    const double A[] = {0.01, 1.3, 40.0};
    for (std::size_t g = 0; g < 3; ++g)
      for (const double R : {0.5, 1.0, 2.0, 4.0}) {
        x[g].push_back(std::log(R));
        y[g].push_back(std::log(A[g] * std::pow(R, n)));
        e[g].push_back(0.01 * (1.0 + static_cast<double>(g)));
      }
    double chi2 = -1.0;
    const RadiusValue v = common_exponent(x, y, e, &chi2);
    EXPECT_NEAR(v.value, n, 1e-12) << "n = " << n;
    EXPECT_NEAR(chi2, 0.0, 1e-20);
    EXPECT_GT(v.error, 0.0);
  }
}

// With Gaussian noise of known relative size (the errors given) the estimates scatter as the
// fit's error says: their spread over 200 draws agrees with 1/sqrt(sum w (x - mean x)^2) within
// 20 %, their mean is 2 within three standard errors, and each is within 4 of its errors (the
// error is rescaled by sqrt(chi2/dof) when the points scatter more than their errors).
TEST(RadiusScaling, ItsErrorIsTheSpreadOfTheEstimate) {
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<double> estimates;
  double stated = 0.0;
  for (int draw = 0; draw < 200; ++draw) {
    std::vector<std::vector<double>> x(2), y(2), e(2);
    for (std::size_t g = 0; g < 2; ++g)
      for (const double R : {0.5, 1.0, 2.0}) {
        x[g].push_back(std::log(R));
        y[g].push_back(std::log(3.0 * (1 + g)) + 2.0 * std::log(R) + noise(rng));
        e[g].push_back(0.05);
      }
    const RadiusValue v = common_exponent(x, y, e);
    EXPECT_LT(std::abs(v.value - 2.0), 4.0 * v.error);
    estimates.push_back(v.value);
    stated = 0.05 / std::sqrt(2.0 * 2.0 * std::log(2.0) * std::log(2.0));  // 1/sqrt(sum w (x - mean)^2), no rescaling
  }
  double m = 0.0, s2 = 0.0;
  for (double v : estimates) m += v;
  m /= static_cast<double>(estimates.size());
  for (double v : estimates) s2 += (v - m) * (v - m);
  const double spread = std::sqrt(s2 / static_cast<double>(estimates.size() - 1));
  EXPECT_NEAR(m, 2.0, 3.0 * spread / std::sqrt(200.0));
  EXPECT_NEAR(spread / stated, 1.0, 0.2);
}

TEST(RadiusScaling, NeedsTwoRadiiInAGroup) {
  const RadiusValue v = common_exponent({{0.0}}, {{1.0}}, {{0.1}});
  EXPECT_TRUE(std::isnan(v.value));
}

}  // namespace
}  // namespace softpack
