// The preregistered criteria (issue 29; experiments/criteria.yaml, paper/preregistration.md):
// the clamped form of Eq. 7, the judgement of a fit, the jackknife, the selection over scenes,
// the zero-mean (prestrain) test and Table 2's unit rule, each on synthetic data with a known answer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/fit_selection.hpp"
#include "analysis/power_fit.hpp"
#include "analysis/verdict.hpp"
#include "config/yaml_node.hpp"

namespace softpack {
namespace {

// A soft-solid-like law: F = 80 dn^2.8 − c with δ = 0.1, zero below; every seed's curve the law
// times (1 + 0.03 g_seed) plus 2 mN of noise per point (seeded, so the test is replayable).
struct Synthetic {
  fit::SceneCurves curves;
  double a = 80.0, b = 2.8, delta = 0.1;
};
Synthetic synthetic(unsigned seeds, double offset = 0.0) {
  Synthetic s;
  std::mt19937_64 rng(29);
  std::normal_distribution<double> g(0.0, 1.0);
  const double c = -s.a * std::pow(s.delta, s.b);
  std::vector<double> gain;
  for (unsigned k = 0; k < seeds; ++k) gain.push_back(1.0 + 0.03 * g(rng));
  for (int i = 0; i <= 20; ++i) {
    const double dn = 0.025 * i;
    const double law = dn >= s.delta ? s.a * std::pow(dn, s.b) + c : 0.0;
    std::vector<double> row;
    for (unsigned k = 0; k < seeds; ++k) row.push_back(law > 0.0 ? law * gain[k] + 2e-3 * g(rng) + offset : 0.0);
    double m = 0.0, v = 0.0;
    for (double x : row) m += x / seeds;
    for (double x : row) v += (x - m) * (x - m);
    s.curves.delta_n.push_back(dn);
    s.curves.Fn.push_back(m);
    s.curves.Fn_stderr.push_back(std::sqrt(v / (seeds - 1.0) / seeds));
    s.curves.Fn_per_seed.push_back(row);
  }
  return s;
}

TEST(Criteria, TheClampedFitRecoversALawThatIsZeroBelowDelta) {
  const Synthetic s = synthetic(7);
  fit::FitOptions o;
  o.form = fit::FitOptions::Form::clamped;
  o.weighting = fit::FitOptions::Weighting::standard_error;
  const fit::PowerLawFit f = fit::fit_normal_law(s.curves.delta_n, s.curves.Fn, s.curves.Fn_stderr, o);
  EXPECT_EQ(f.points, s.curves.delta_n.size());  // every point, the zeros before the onset too
  EXPECT_NEAR(f.b, s.b, 0.1);
  EXPECT_NEAR(f.delta, s.delta, 0.01);
  EXPECT_NEAR(f.a / s.a, 1.0, 0.1);
}

TEST(Criteria, TheJudgementSeesAMisfitThatTheLoadedPointsHide) {
  const Synthetic s = synthetic(7);
  fit::PowerLawFit right;
  right.a = s.a, right.b = s.b, right.c = -s.a * std::pow(s.delta, s.b), right.delta = s.delta;
  const fit::Judgement good = fit::judge_normal_law(right, s.curves.delta_n, s.curves.Fn, s.curves.Fn_stderr, 1e-3, 0.5);
  EXPECT_EQ(good.points, s.curves.delta_n.size());
  EXPECT_LT(good.chi2_per_dof, 3.0);
  // A law with its onset moved by 0.05: every point between the two onsets misfits, in one run.
  fit::PowerLawFit late = right;
  late.delta = 0.15, late.c = -late.a * std::pow(late.delta, late.b);
  const fit::Judgement bad = fit::judge_normal_law(late, s.curves.delta_n, s.curves.Fn, s.curves.Fn_stderr, 1e-3, 0.5);
  EXPECT_GT(bad.chi2_per_dof, 10.0 * good.chi2_per_dof);
  EXPECT_EQ(bad.runs, 1u);  // every residual of one sign: no runs test, and not adequate
  EXPECT_TRUE(std::isnan(bad.runs_z));
  // A law of the wrong exponent through the curve at dn = 0.3: below it on one side, above on
  // the other, so the residuals come in two long runs.
  fit::PowerLawFit flat;
  flat.b = 2.0, flat.delta = s.delta;
  flat.a = (s.a * std::pow(0.3, s.b) + right.c) / (std::pow(0.3, 2.0) - std::pow(s.delta, 2.0));
  flat.c = -flat.a * std::pow(flat.delta, flat.b);
  const fit::Judgement runs = fit::judge_normal_law(flat, s.curves.delta_n, s.curves.Fn, s.curves.Fn_stderr, 1e-3, 0.5);
  EXPECT_LE(runs.runs, 3u);
  EXPECT_LT(runs.runs_z, -2.58);
}

TEST(Criteria, TheJackknifeErrorGrowsWithTheSpreadOfTheSeeds) {
  const fit::FitCriteria criteria;
  fit::Candidate c{"clamped", {}};
  c.options.form = fit::FitOptions::Form::clamped;
  const fit::CandidateFit one = fit::fit_candidate(c, synthetic(7).curves, criteria);
  ASSERT_TRUE(one.jackknife.done) << one.jackknife.reason;
  EXPECT_EQ(one.jackknife.samples, 7u);
  EXPECT_GT(one.jackknife.b, 0.0);
  EXPECT_TRUE(one.stable);
  // Without per-seed values there is no jackknife, and an unmeasured stability is not stability.
  fit::SceneCurves bare = synthetic(7).curves;
  bare.Fn_per_seed.clear();
  const fit::CandidateFit none = fit::fit_candidate(c, bare, criteria);
  EXPECT_FALSE(none.jackknife.done);
  EXPECT_FALSE(none.stable);
}

TEST(Criteria, TheSelectionTakesTheLeastWorseSceneChi2AmongTheStable) {
  fit::FitCriteria criteria;
  criteria.candidates = {{"x", {}}, {"y", {}}, {"z", {}}};
  const auto cand = [](const char* name, double chi2, bool stable) {
    fit::CandidateFit c;
    c.name = name;
    c.normal = fit::PowerLawFit{};
    c.judged.chi2_per_dof = chi2;
    c.stable = stable;
    return c;
  };
  // z fits best but is unstable in one scene; y's worse scene (1.5) beats x's (3).
  const std::vector<std::vector<fit::CandidateFit>> scenes{{cand("x", 3.0, true), cand("y", 1.5, true), cand("z", 0.5, false)},
                                                           {cand("x", 1.0, true), cand("y", 1.2, true), cand("z", 0.4, true)}};
  EXPECT_EQ(fit::select_fit(scenes, criteria).chosen, 1u);
  // None stable: all are considered.
  const std::vector<std::vector<fit::CandidateFit>> unstable{{cand("x", 3.0, false), cand("y", 1.5, false), cand("z", 0.5, false)}};
  EXPECT_EQ(fit::select_fit(unstable, criteria).chosen, 2u);
}

TEST(Criteria, StudentTMatchesItsTables) {
  EXPECT_NEAR(verdict::student_t_two_sided_p(12.706, 1), 0.05, 1e-4);
  EXPECT_NEAR(verdict::student_t_two_sided_p(4.303, 2), 0.05, 1e-4);
  EXPECT_NEAR(verdict::student_t_two_sided_p(2.447, 6), 0.05, 1e-4);
  EXPECT_NEAR(verdict::student_t_two_sided_p(3.707, 6), 0.01, 1e-4);
  EXPECT_NEAR(verdict::student_t_two_sided_p(0.0, 5), 1.0, 1e-12);
  EXPECT_NEAR(verdict::chi2_survival(7.815, 3), 0.05, 1e-4);
  EXPECT_NEAR(verdict::chi2_survival(9.488, 4), 0.05, 1e-4);
}

TEST(Criteria, APrestrainThatAveragesOutPassesAndACommonOffsetFails) {
  std::mt19937_64 rng(401);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<std::vector<double>> independent(7), offset(7);
  for (std::size_t k = 0; k < 7; ++k)
    for (int s = 0; s < 7; ++s) {
      const double x = 0.01 * g(rng);
      independent[k].push_back(x);
      offset[k].push_back(x + 0.02);  // every seed shifted alike: it never averages out
    }
  EXPECT_GT(verdict::zero_mean_test(independent).p, 0.01);
  EXPECT_LT(verdict::zero_mean_test(offset).p, 0.01);
}

}  // namespace
}  // namespace softpack
