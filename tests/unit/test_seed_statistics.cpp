// The statistics over seeds (analysis/seed_statistics.hpp): the mean and standard error of the
// mean, the jackknife standard error and covariance, against values computed by hand; what each
// says for fewer than two seeds; and the one order of operations, which the archived averages
// and fits hold bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/seed_statistics.hpp"

namespace softpack {
namespace {

// {1, 2, 3, 4}: mean 5/2, Σ (x − mean)² = 5, s² = 5/3, standard error √(5/3 / 4) = √(5/12).
const std::vector<double> kSeedStatisticsValues{1.0, 2.0, 3.0, 4.0};
const double kSeedStatisticsError = std::sqrt(5.0 / 12.0);  // 0.6454972243679028
constexpr double kSeedStatisticsTolerance = 1e-15;         // a few ulps of values of order 1

TEST(SeedStatistics, MeanAndStandardErrorAsComputedByHand) {
  for (FewSeeds form : {FewSeeds::zero, FewSeeds::not_known}) {
    const MeanError m = mean_error(kSeedStatisticsValues, form);
    EXPECT_NEAR(m.mean, 2.5, kSeedStatisticsTolerance);
    EXPECT_NEAR(m.error, kSeedStatisticsError, kSeedStatisticsTolerance);
  }
  // A constant has no spread.
  EXPECT_EQ(mean_error({0.7, 0.7, 0.7}).error, 0.0);
}

TEST(SeedStatistics, TheJackknifeOfTheMeanIsItsStandardError) {
  // Leaving each seed out of {1, 2, 3, 4} in turn: means 3, 8/3, 7/3, 2; Σ (θ_j − 5/2)² = 5/9,
  // times (n − 1)/n = 3/4: 5/12, the standard error's square (an identity of the mean).
  const std::vector<double> theta{3.0, 8.0 / 3.0, 7.0 / 3.0, 2.0};
  EXPECT_NEAR(jackknife_error(theta), kSeedStatisticsError, kSeedStatisticsTolerance);
  // The covariance of four coefficients: θ, 2θ, a constant and −θ.
  std::vector<Eigen::Vector4d> coefficients;
  for (double t : theta) coefficients.push_back(Eigen::Vector4d{t, 2.0 * t, 5.0, -t});
  const Eigen::Matrix4d cov = jackknife_covariance(coefficients);
  const double v = 5.0 / 12.0;
  EXPECT_NEAR(cov(0, 0), v, kSeedStatisticsTolerance);
  EXPECT_NEAR(cov(1, 1), 4.0 * v, 4.0 * kSeedStatisticsTolerance);
  EXPECT_NEAR(cov(0, 1), 2.0 * v, 2.0 * kSeedStatisticsTolerance);
  EXPECT_NEAR(cov(1, 0), 2.0 * v, 2.0 * kSeedStatisticsTolerance);
  EXPECT_NEAR(cov(0, 3), -v, kSeedStatisticsTolerance);
  EXPECT_EQ(cov(2, 2), 0.0);
  EXPECT_NEAR(std::sqrt(cov(0, 0)), kSeedStatisticsError, kSeedStatisticsTolerance);
}

TEST(SeedStatistics, FewerThanTwoSeedsHaveNoError) {
  // The NaN forms: not known.
  const MeanError one = mean_error({7.0}, FewSeeds::not_known);
  EXPECT_EQ(one.mean, 7.0);
  EXPECT_TRUE(std::isnan(one.error));
  const MeanError none = mean_error({}, FewSeeds::not_known);
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_TRUE(std::isnan(none.error));
  EXPECT_TRUE(std::isnan(jackknife_error({3.0})));
  EXPECT_TRUE(std::isnan(jackknife_error({})));
  EXPECT_TRUE(jackknife_covariance(std::vector<Eigen::Vector4d>(1, Eigen::Vector4d::Ones())).array().isNaN().all());
  // The average files' form: finite, so that a fit weighted by the errors reads it (0, unweighted).
  const MeanError average = mean_error({7.0});
  EXPECT_EQ(average.mean, 7.0);
  EXPECT_EQ(average.error, 0.0);
  EXPECT_EQ(mean_error({}).mean, 0.0);
  EXPECT_EQ(mean_error({}).error, 0.0);
}

// The one order of operations, the archived averages' and fits' (the regression tests compare
// the archive bit for bit): mean Σ (x / n); the jackknife's spread times ((n − 1) / n).
TEST(SeedStatistics, OneOrderOfOperations) {
  std::mt19937_64 rng(30);
  std::normal_distribution<double> g(1.0, 0.3);
  std::vector<double> v;
  for (int k = 0; k < 7; ++k) v.push_back(g(rng));
  const double n = static_cast<double>(v.size());
  double mean = 0.0;
  for (double x : v) mean += x / n;
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  for (FewSeeds few : {FewSeeds::zero, FewSeeds::not_known}) {
    EXPECT_EQ(mean_error(v, few).mean, mean);
    EXPECT_EQ(mean_error(v, few).error, std::sqrt(ss / (n - 1.0) / n));
  }
  EXPECT_EQ(jackknife_error(v), std::sqrt(ss * ((n - 1.0) / n)));
  std::vector<Eigen::Vector4d> theta;
  for (double x : v) theta.push_back(Eigen::Vector4d::Constant(x));
  EXPECT_EQ(jackknife_covariance(theta)(1, 1), ss * ((n - 1.0) / n));
  EXPECT_EQ(std::sqrt(jackknife_covariance(theta)(2, 2)), jackknife_error(v));
}

}  // namespace
}  // namespace softpack
