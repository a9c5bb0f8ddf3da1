// The profile's `fit` section (analysis/fit_options.hpp, docs/fit.md): grazing forces before the
// onset, the upper bound of Δn, the weightings, and what a bad section is refused with.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/fit_options.hpp"
#include "analysis/power_fit.hpp"
#include "core/error.hpp"
#include "unit/fit_series.hpp"

namespace {
using softpack::fit::fit_normal_law;
using softpack::fit::fit_tangential_law;
using namespace softpack::fit_test;
}  // namespace

namespace {
using softpack::fit::FitOptions;
using softpack::fit::PowerLawFit;
using softpack::InputError;

/// Eq. 7 with δ = 0.15 on Δn = 0, 0.025, …, 0.5, and grazing forces before the onset: a few
/// grains the relaxation leaves touching (1e-8 N at 0.1, 3e-7 N at 0.125, 2e-6 N at 0.15, where
/// the law itself is 0), with standard errors of their own size, as the seed averages have them.
Series grazing_series(const Law& law) {
  Series s;
  for (int k = 0; k <= 20; ++k) {
    const double x = 0.025 * k, f = law(x);
    s.x.push_back(x);
    s.y.push_back(f);
    s.e.push_back(f > 0.0 ? 0.02 * f + 1e-3 * law(0.5) : 0.0);
  }
  s.y[4] = 1e-8, s.e[4] = 1e-8;
  s.y[5] = 3e-7, s.e[5] = 3e-7;
  s.y[6] = 2e-6, s.e[6] = 2e-6;
  return s;
}
const Law kLateOnset{"late onset", 50.0, 3.0, -50.0 * 0.15 * 0.15 * 0.15};
}  // namespace

TEST(FitOptions, GrazingForcesBeforeTheOnsetMoveTheDefaultFitButNotAnOnsetThreshold) {
  const Series s = grazing_series(kLateOnset);
  // The default (any force above round-off is loaded, 1/stderr^2): the grazing points start the
  // fitted run and pin δ below them, far from the law's 0.15.
  const PowerLawFit loose = fit_normal_law(s.x, s.y, s.e);
  EXPECT_LT(loose.delta, 0.125);
  EXPECT_DOUBLE_EQ(loose.dn_min, 0.1);
  // Loaded above 1% of the largest force: the law itself, whatever the weighting.
  for (const auto w : {FitOptions::Weighting::standard_error, FitOptions::Weighting::unweighted,
                       FitOptions::Weighting::relative}) {
    FitOptions o;
    o.weighting = w;
    o.onset_force = 1e-2;
    const PowerLawFit f = fit_normal_law(s.x, s.y, s.e, o);
    SCOPED_TRACE(softpack::fit::weighting_name(w));
    EXPECT_EQ(f.weighting, softpack::fit::weighting_name(w));
    EXPECT_NEAR(f.delta, 0.15, 1e-6);
    EXPECT_NEAR(f.b, kLateOnset.b, 1e-6);
    EXPECT_NEAR(f.a / kLateOnset.a, 1.0, 1e-6);
    EXPECT_NEAR(f.onset_force, 1e-2 * kLateOnset(0.5), 1e-12);
    EXPECT_GT(f.dn_min, 0.15);
  }
}

TEST(FitOptions, DeltaNMaxBoundsBothLaws) {
  Series s = normal_series(kSoftSolid, nullptr);
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (s.x[i] > 0.4) s.y[i] *= 10.0;  // beyond the bound: not Eq. 7 at all
  FitOptions o;
  o.delta_n_max = 0.4;
  const PowerLawFit f = fit_normal_law(s.x, s.y, s.e, o);
  EXPECT_DOUBLE_EQ(f.dn_max, 0.4);
  EXPECT_NEAR(f.b, kSoftSolid.b, 1e-6);
  bool said = false;
  for (const auto& note : f.notes) said = said || note.find("left out: delta_n above delta_n_max = 0.4 (8 points)") != std::string::npos;
  EXPECT_TRUE(said);

  std::vector<double> x, kt, e;
  for (double dn = 0.2; dn <= 0.5001; dn += 0.05) {
    x.push_back(dn);
    kt.push_back(dn > 0.4 ? 1e6 : 0.74 * (std::pow(dn, 2.1) - std::pow(0.1, 2.1)));
    e.push_back(0.01);
  }
  const PowerLawFit t = fit_tangential_law(x, kt, e, 0.1, o);
  EXPECT_NEAR(t.b, 2.1, 1e-6);
  EXPECT_LE(t.dn_max, 0.4 + 1e-12);
}

TEST(FitOptions, RelativeWeightingCountsEveryDecadeAlike) {
  // Multiplicative noise (±5%, alternating) on a law spanning four decades: weighted by 1/value^2
  // every point counts by its relative deviation, and b is recovered within 2%; unweighted, the
  // largest forces decide alone.
  const Law law{"decades", 30.0, 5.0, -30.0 * std::pow(0.15, 5.0)};
  std::vector<double> x, y;
  for (int k = 7; k <= 20; ++k) {
    const double dn = 0.025 * k;
    x.push_back(dn);
    y.push_back(law(dn) * (k % 2 ? 1.05 : 0.95));
  }
  FitOptions o;
  o.weighting = FitOptions::Weighting::relative;
  const PowerLawFit f = fit_normal_law(x, y, {}, o);
  EXPECT_TRUE(f.weighted);
  EXPECT_NEAR(f.b / law.b, 1.0, 0.02);
  EXPECT_NEAR(f.delta / law.delta(), 1.0, 0.05);
}

TEST(FitOptions, BadOptionsAreRefused) {
  const Series s = normal_series(kSoftSolid, nullptr);
  FitOptions o;
  o.onset_force = 1.0;
  EXPECT_THROW(fit_normal_law(s.x, s.y, s.e, o), InputError);
  o = {};
  o.delta_n_max = 0.0;
  EXPECT_THROW(fit_normal_law(s.x, s.y, s.e, o), InputError);
  EXPECT_THROW(softpack::fit::parse_weighting("chi2"), InputError);
}
