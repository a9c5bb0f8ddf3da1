// The fits of Eqs. 7 and 8 (analysis/power_fit.hpp): exact data is recovered to 1e-6, noisy
// data within 3 of the stated standard errors, the errors are calibrated (about 68% of fits
// within one standard error), and too few points give a message with the count and the onset.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/power_fit.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "formats/fit_file.hpp"
#include "unit/fit_series.hpp"

namespace {

using softpack::InputError;
using softpack::Random;
using softpack::fit::fit_normal_law;
using softpack::fit::fit_tangential_law;
using softpack::fit::PowerLawFit;
using namespace softpack::fit_test;


TEST(PowerFit, NormalLawExactDataIsRecovered) {
  for (const Law& law : {kSoftSolid, kSoftSoft, kSteep}) {
    const Series s = normal_series(law, nullptr);
    for (bool weighted : {true, false}) {
      const PowerLawFit f = fit_normal_law(s.x, s.y, weighted ? std::span<const double>(s.e) : std::span<const double>());
      SCOPED_TRACE(std::string(law.name) + (weighted ? ", weighted" : ", unweighted"));
      EXPECT_EQ(f.weighted, weighted);
      EXPECT_NEAR(f.a / law.a, 1.0, 1e-6);
      EXPECT_NEAR(f.b, law.b, 1e-6);
      EXPECT_NEAR(f.c, law.c, 1e-6);
      EXPECT_NEAR(f.delta, law.delta(), 1e-6);
      EXPECT_LT(f.chi2_per_dof, 1e-12);
      EXPECT_GE(f.points, 4u);
      EXPECT_GT(f.dn_min, law.delta());
      EXPECT_LE(f.dn_min - 0.0125, law.delta());
      EXPECT_DOUBLE_EQ(f.dn_max, 0.5);
    }
  }
}

TEST(PowerFit, NormalLawNoisyDataWithinThreeStandardErrors) {
  for (const Law& law : {kSoftSolid, kSoftSoft, kSteep}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      Random rng(seed);
      const Series s = normal_series(law, &rng);
      const PowerLawFit f = fit_normal_law(s.x, s.y, s.e);
      const std::string what = std::string(law.name) + " seed " + std::to_string(seed);
      EXPECT_TRUE(f.weighted) << what;
      EXPECT_GT(f.a_error, 0.0) << what;
      EXPECT_GT(f.delta_error, 0.0) << what;
      expect_within(f.a, f.a_error, law.a, 3.0, what + " a");
      expect_within(f.b, f.b_error, law.b, 3.0, what + " b");
      expect_within(f.c, f.c_error, law.c, 3.0, what + " c");
      expect_within(f.delta, f.delta_error, law.delta(), 3.0, what + " delta");
      // The weights are the true σ: χ²/dof near 1.
      EXPECT_GT(f.chi2_per_dof, 0.2) << what;
      EXPECT_LT(f.chi2_per_dof, 3.0) << what;
    }
  }
}

TEST(PowerFit, NormalLawStandardErrorsAreCalibrated) {
  // Over 200 noisy data sets about 68% of the fits lie within one standard error of the truth
  // (binomial sd 3.3%), about 95% within two.
  int within1[4] = {0, 0, 0, 0}, within2[4] = {0, 0, 0, 0};
  const int n = 200;
  for (int seed = 0; seed < n; ++seed) {
    Random rng(1000 + static_cast<std::uint64_t>(seed));
    const Series s = normal_series(kSoftSolid, &rng);
    const PowerLawFit f = fit_normal_law(s.x, s.y, s.e);
    const double dev[4] = {(f.a - kSoftSolid.a) / f.a_error, (f.b - kSoftSolid.b) / f.b_error,
                           (f.c - kSoftSolid.c) / f.c_error, (f.delta - kSoftSolid.delta()) / f.delta_error};
    for (int k = 0; k < 4; ++k) within1[k] += std::abs(dev[k]) < 1.0, within2[k] += std::abs(dev[k]) < 2.0;
  }
  const char* names[4] = {"a", "b", "c", "delta"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(within1[k], 0.55 * n) << names[k];
    EXPECT_LT(within1[k], 0.80 * n) << names[k];
    EXPECT_GT(within2[k], 0.88 * n) << names[k];
  }
}

TEST(PowerFit, NormalLawWithoutErrorsOrWithAZeroErrorIsUnweighted) {
  Series s = normal_series(kSoftSolid, nullptr);
  const PowerLawFit none = fit_normal_law(s.x, s.y, {});
  EXPECT_FALSE(none.weighted);
  ASSERT_FALSE(none.notes.empty());
  EXPECT_NE(none.notes.front().find("no standard errors"), std::string::npos) << none.notes.front();
  s.e.back() = 0.0;
  const PowerLawFit zero = fit_normal_law(s.x, s.y, s.e);
  EXPECT_FALSE(zero.weighted);
  EXPECT_NE(zero.notes.front().find("standard error is 0 at delta_n = 0.5"), std::string::npos) << zero.notes.front();
  EXPECT_NEAR(zero.b, kSoftSolid.b, 1e-6);
}

TEST(PowerFit, NormalLawWithPositiveCHasNoThreshold) {
  const Law hertz_like{"positive c", 93.8, 1.5, 0.01};
  std::vector<double> x, y;
  for (int k = 1; k <= 20; ++k) x.push_back(0.025 * k), y.push_back(hertz_like.a * std::pow(0.025 * k, 1.5) + 0.01);
  const PowerLawFit f = fit_normal_law(x, y, {});
  EXPECT_NEAR(f.c, 0.01, 1e-6);
  EXPECT_EQ(f.delta, 0.0);
  EXPECT_TRUE(std::isnan(f.delta_error));
  bool said = false;
  for (const auto& note : f.notes) said = said || note.find("delta = 0") != std::string::npos;
  EXPECT_TRUE(said);
  // The fit file writes the undefined error as null.
  softpack::FitFile file;
  file.normal = f;
  EXPECT_NE(softpack::fit_file_text(file).find("\"delta_error\": null"), std::string::npos);
}

TEST(PowerFit, NormalLawLeavesOutAPositivePointBeforeAZero) {
  Series s = normal_series(kSoftSolid, nullptr);
  s.y[2] = 1e-4;  // Δn = 0.025, below δ = 0.065, followed by zeros
  const PowerLawFit f = fit_normal_law(s.x, s.y, {});
  EXPECT_NEAR(f.delta, kSoftSolid.delta(), 1e-6);
  bool said = false;
  for (const auto& note : f.notes) said = said || note.find("left out: positive force before a zero at delta_n = 0.025") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(PowerFit, NormalLawTreatsRoundOffForcesAsZero) {
  // A net force of 1e-19 N (grain forces that cancel up to round-off) just below the onset is
  // zero, not the start of the positive run: the fit and its point count are unchanged.
  Series s = normal_series(kSoftSolid, nullptr);
  const PowerLawFit clean = fit_normal_law(s.x, s.y, {});
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (s.y[i] == 0.0) s.y[i] = 1e-19;
  const PowerLawFit f = fit_normal_law(s.x, s.y, {});
  EXPECT_EQ(f.points, clean.points);
  EXPECT_NEAR(f.delta, kSoftSolid.delta(), 1e-6);
  EXPECT_TRUE(f.notes.empty() || f.notes.front().find("left out") == std::string::npos);
}

TEST(PowerFit, NormalLawRefusesTooFewPoints) {
  const std::vector<double> x{0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.5};
  const std::vector<double> y{0.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.4};
  try {
    fit_normal_law(x, y, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("2 points with Fn > 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("the force starts at delta_n = 0.45"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at least 4"), std::string::npos) << msg;
  }
  const std::vector<double> zeros(x.size(), 0.0);
  try {
    fit_normal_law(x, zeros, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0 points with Fn > 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fit_normal_law(x, std::vector<double>{1.0, 2.0}, {}), InputError);
  std::vector<double> nan = y;
  nan[3] = std::nan("");
  EXPECT_THROW(fit_normal_law(x, nan, {}), InputError);
}

/// Eq. 8 on Δn = 0.2, 0.25, …, 0.5 (the paper profile's shear grid) with σ = 3% of kt.
Series tangential_series(double a, double b, double delta, Random* rng) {
  Series s;
  for (int k = 0; k <= 6; ++k) {
    const double x = 0.2 + 0.05 * k, kt = a * (std::pow(x, b) - std::pow(delta, b));
    const double sigma = 0.03 * kt;
    s.x.push_back(x);
    s.y.push_back(rng ? kt + sigma * gaussian(*rng) : kt);
    s.e.push_back(sigma);
  }
  return s;
}

TEST(PowerFit, TangentialLawRecoversAAndBGivenDelta) {
  struct Case {
    double a, b, delta;
  };
  for (const Case& c : {Case{0.740, 2.100, 0.065}, Case{0.982, 4.422, 0.148}, Case{500.0, 3.0, 0.15}}) {
    const Series exact = tangential_series(c.a, c.b, c.delta, nullptr);
    const PowerLawFit f = fit_tangential_law(exact.x, exact.y, exact.e, c.delta);
    EXPECT_NEAR(f.a / c.a, 1.0, 1e-6);
    EXPECT_NEAR(f.b, c.b, 1e-6);
    EXPECT_NEAR(f.c, -c.a * std::pow(c.delta, c.b), 1e-6 * c.a);
    EXPECT_EQ(f.delta, c.delta);
    EXPECT_EQ(f.points, 7u);
    EXPECT_EQ(f.covariance.rows(), 2);
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      Random rng(seed);
      const Series s = tangential_series(c.a, c.b, c.delta, &rng);
      const PowerLawFit g = fit_tangential_law(s.x, s.y, s.e, c.delta);
      const std::string what = "a " + std::to_string(c.a) + " seed " + std::to_string(seed);
      expect_within(g.a, g.a_error, c.a, 3.0, what + " a");
      expect_within(g.b, g.b_error, c.b, 3.0, what + " b");
      expect_within(g.c, g.c_error, -c.a * std::pow(c.delta, c.b), 3.0, what + " c");
      EXPECT_GT(g.c_error, 0.0);
    }
  }
}

TEST(PowerFit, TangentialLawUsesOnlyPointsAboveDeltaWithPositiveKt) {
  Series s = tangential_series(0.74, 2.1, 0.065, nullptr);
  s.x.insert(s.x.begin(), 0.05);  // below δ: ignored
  s.y.insert(s.y.begin(), 5.0);
  s.e.insert(s.e.begin(), 1.0);
  s.y[3] = -0.01;  // kt <= 0: left out
  const PowerLawFit f = fit_tangential_law(s.x, s.y, s.e, 0.065);
  EXPECT_EQ(f.points, 6u);
  EXPECT_NEAR(f.b, 2.1, 1e-6);
  EXPECT_DOUBLE_EQ(f.dn_min, 0.2);
}

TEST(PowerFit, TangentialLawRefusesTooFewPoints) {
  const std::vector<double> x{0.2, 0.3, 0.4, 0.5}, kt{0.0, -0.1, 0.2, 0.3};
  try {
    fit_tangential_law(x, kt, {}, 0.15);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("2 points with delta_n > delta = 0.15 and kt > 0 (at delta_n = 0.4, 0.5)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at least 3"), std::string::npos) << msg;
  }
  EXPECT_THROW(fit_tangential_law(x, kt, {}, std::nan("")), InputError);
  EXPECT_THROW(fit_tangential_law(x, kt, {}, -0.1), InputError);
}

// The fit file (formats/fit_file.hpp): what softpack-fit writes, softpack-table reads back.
TEST(PowerFit, FitFileRoundTrip) {
  const Series s = normal_series(kSoftSolid, nullptr);
  softpack::FitFile file;
  file.scene = "soft-solid";
  file.normal = fit_normal_law(s.x, s.y, s.e);
  file.tangential_reason = "no /kt group";
  const PowerLawFit& f = file.normal;
  const std::string text = softpack::fit_file_text(file);
  for (const char* key : {"\"a\"", "\"a_error\"", "\"b\"", "\"b_error\"", "\"c\"", "\"c_error\"", "\"delta\"",
                          "\"delta_error\"", "\"points\"", "\"weighted\"", "\"chi2_per_dof\"", "\"range\"",
                          "\"tangential_reason\""})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  const std::string path = ::testing::TempDir() + "softpack-" + std::to_string(::getpid()) + "-fit.json";
  softpack::write_fit_file(path, file);
  const auto e = softpack::read_fit_file(path);
  EXPECT_EQ(e.scene, "soft-solid");
  EXPECT_EQ(e.normal.at("a").value, f.a);
  EXPECT_EQ(e.normal.at("delta").error, f.delta_error);
  EXPECT_FALSE(e.tangential.has_value());
  std::ofstream(path) << R"({"scene": "soft-solid", "normal": {"a": 1.0}})";
  try {
    softpack::read_fit_file(path);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("fit.json: normal.b: missing"), std::string::npos) << err.what();
  }
  std::remove(path.c_str());
}

}  // namespace

