// The nested report's judgement (report/nested_report.hpp): the criterion read from
// experiments/nested.yaml, and a setting against the resolved one point by point — within
// bound √(se² + se²) agrees, beyond does not, below the onset force (scaled with (Rs / Rs0)²) in
// both is left out, for kt by the Fn at its Δn; the ratio's error propagated.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "report/nested_report.hpp"

namespace softpack {
namespace {

NestedSetting setting(const std::string& name, double Rs, std::vector<RadiusValue> Fn, std::vector<RadiusValue> kt) {
  NestedSetting s;
  s.name = name, s.Rs = Rs, s.ran = true;
  RadiusRow row;
  row.setting = name, row.scene = "soft-solid", row.Fn = std::move(Fn), row.kt = std::move(kt);
  s.rows = {row};
  return s;
}

TEST(NestedReport, TheCriterionIsTheCommittedOne) {
  const NestedCriterion c = read_nested_criterion(SOFTPACK_SOURCE_DIR "/experiments/nested.yaml");
  EXPECT_EQ(c.Fn_delta_n[0], 0.2);
  EXPECT_EQ(c.Fn_delta_n[1], 0.5);
  EXPECT_EQ(c.kt_delta_n[0], 0.2);
  EXPECT_EQ(c.kt_delta_n[1], 0.5);
  EXPECT_EQ(c.bound, 2.0);
  EXPECT_EQ(c.onset_force, 1e-3);
  EXPECT_EQ(c.Rs0, 0.016);
  EXPECT_EQ(c.diagnosis, (std::vector<std::string>{"grains-reduced", "many-body"}));
  EXPECT_THROW(read_nested_criterion(""), InputError);
}

TEST(NestedReport, PointsAgreeWithinTheBoundAndBelowTheOnsetAreLeftOut) {
  NestedCriterion c;
  c.Fn_delta_n = {0.2, 0.5}, c.kt_delta_n = {0.2, 0.5};
  c.bound = 2.0, c.onset_force = 1e-3, c.Rs0 = 0.016;
  // At Rs = Rs0 / 10 the onset is 1e-5 N.
  const double Rs = 0.0016;
  const std::vector<double> Fn_dn{0.2, 0.3, 0.4}, kt_dn{0.2, 0.4};
  const NestedSetting nested = setting("nested", Rs, {{5e-6, 1e-6}, {1.0, 0.1}, {2.0, 0.1}}, {{3.0, 1.0}, {10.0, 1.0}});
  const NestedSetting resolved = setting("resolved", Rs, {{4e-6, 1e-6}, {1.2, 0.1}, {3.0, 0.1}}, {{1.0, 1.0}, {10.5, 0.5}});
  const NestedComparison cmp = nested_comparison(nested, resolved, c, Fn_dn, kt_dn);
  ASSERT_EQ(cmp.points.size(), 5u);
  EXPECT_FALSE(cmp.points[0].compared);  // Fn 5e-6 and 4e-6 N: both below 1e-5 N
  EXPECT_TRUE(cmp.points[1].compared);
  EXPECT_TRUE(cmp.points[1].agrees);     // |1.0 - 1.2| = 0.2 <= 2 √0.02 = 0.283
  EXPECT_FALSE(cmp.points[2].agrees);    // |2 - 3| = 1 > 0.283
  EXPECT_FALSE(cmp.points[3].compared);  // kt at 0.2, where Fn is below the onset in both
  EXPECT_TRUE(cmp.points[4].agrees);     // |10 - 10.5| <= 2 √1.25
  EXPECT_EQ(cmp.compared, 3u);
  EXPECT_EQ(cmp.agreeing, 2u);
  EXPECT_FALSE(cmp.holds());
  EXPECT_NEAR(cmp.points[1].ratio.value, 1.0 / 1.2, 1e-15);
  EXPECT_NEAR(cmp.points[1].ratio.error, (1.0 / 1.2) * std::hypot(0.1, 0.1 / 1.2), 1e-15);
  // At Rs0 the onset is 1e-3 N: the first point is left out all the more; the rest as above.
  EXPECT_EQ(nested_comparison(setting("a", 0.016, {{1.0, 0.1}}, {}), setting("b", 0.016, {{1.1, 0.1}}, {}), c, {0.3}, {}).agreeing, 1u);
}

// Where a soft-particle carries no force yet: up to the last Δn of the range where the mean is
// below the onset at every point before it, NaN when loaded at the first.
TEST(NestedReport, UnloadedToTheLastPointBelowTheOnsetFromTheFirst) {
  NestedCriterion c;
  c.onset_force = 1e-3, c.Rs0 = 0.016;  // 1e-5 N at Rs0 / 10
  const std::vector<double> dn{0.2, 0.3, 0.4, 0.5};
  const auto to = [&](std::vector<RadiusValue> Fn) { return nested_unloaded_to(setting("s", 0.0016, Fn, {}).rows[0], dn, c, 0.0016); };
  EXPECT_EQ(to({{0.0, 0.0}, {9e-6, 1e-6}, {2e-5, 1e-6}, {0.0, 0.0}}), 0.3);  // loaded at 0.4: a later zero does not count
  EXPECT_EQ(to({{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}}), 0.5);
  EXPECT_TRUE(std::isnan(to({{1e-5, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}})));  // at the onset: loaded
  EXPECT_EQ(nested_unloaded_to(setting("s", 0.016, {{9e-4, 0.0}, {2e-3, 0.0}}, {}).rows[0], dn, c, 0.016), 0.2);  // 1e-3 N at Rs0
}

// A diagnosis setting against the reference (experiments/nested.yaml): nearer the resolved mean
// at every point compared in both is a cause of the gap; at one point farther, not.
TEST(NestedReport, ASettingNearerTheResolvedAtEveryPointIsACauseOfTheGap) {
  NestedCriterion c;
  c.Fn_delta_n = {0.2, 0.5}, c.kt_delta_n = {0.2, 0.5};
  c.bound = 2.0, c.onset_force = 1e-3, c.Rs0 = 0.016;
  const std::vector<double> Fn_dn{0.3, 0.4}, kt_dn{0.4};
  const NestedSetting resolved = setting("resolved", 0.016, {{1.0, 0.01}, {2.0, 0.01}}, {{10.0, 0.1}});
  const NestedSetting reference = setting("reference", 0.016, {{0.3, 0.01}, {0.6, 0.01}}, {{4.0, 0.1}});
  const NestedSetting nearer = setting("nearer", 0.016, {{0.8, 0.01}, {1.5, 0.01}}, {{11.0, 0.1}});
  const NestedSetting mixed = setting("mixed", 0.016, {{0.8, 0.01}, {0.5, 0.01}}, {{9.0, 0.1}});
  const NestedComparison ref = nested_comparison(reference, resolved, c, Fn_dn, kt_dn);
  NestedComparison a = nested_comparison(nearer, resolved, c, Fn_dn, kt_dn);
  NestedComparison b = nested_comparison(mixed, resolved, c, Fn_dn, kt_dn);
  nested_closer(a, ref);
  nested_closer(b, ref);
  EXPECT_EQ(a.closer_of, 3u);
  EXPECT_EQ(a.closer, 3u);  // |0.8 - 1| < |0.3 - 1|, |1.5 - 2| < |0.6 - 2|, |11 - 10| < |4 - 10|
  EXPECT_TRUE(a.cause());
  EXPECT_FALSE(a.holds());  // nearer is not within the bound: a cause, not the whole
  EXPECT_EQ(b.closer, 2u);  // |0.5 - 2| > |0.6 - 2|
  EXPECT_FALSE(b.cause());
}

// One seed's sliding sweep at one Δn: Ft / Fn = mu at every ht (alpha 0: Fn = Fx, Ft = -Fy), or
// no normal force at all.
SweepResults sliding(double dn, double mu, bool loaded) {
  SweepResults s;
  for (double ht : {0.001, 0.002, 0.004}) {
    s.delta_n.push_back(dn), s.ht.push_back(ht), s.alpha_deg.push_back(0.0);
    s.force.push_back(loaded ? Vec3(2.0, -2.0 * mu, 0.0) : Vec3::Zero());
  }
  return s;
}

// mu_soft at a sliding Δn (radius_report.hpp's sliding_friction): over every seed by default; a
// seed whose contact carries no normal force leaves it unmeasured, unless the study's
// nested.mu_seeds_loaded allows fewer — then the mean over the loaded seeds, with a note.
TEST(NestedReport, MuSoftFromTheLoadedSeedsWhenTheStudyAllowsFewerThanEvery) {
  const std::vector<SweepResults> seeds{sliding(0.9, 0.2, true), sliding(0.9, 0.4, true), sliding(0.9, 0.0, false)};
  const double Rs = 0.01, from = 0.15;  // the points at ht / Rs 0.2 and 0.4
  RadiusRow every, two, three;
  sliding_friction(seeds, {0.9}, Rs, from, 0, every);
  ASSERT_EQ(every.mu.size(), 1u);
  EXPECT_TRUE(std::isnan(every.mu[0].value));
  EXPECT_NE(every.note.find("a seed has no normal force while sliding"), std::string::npos);
  sliding_friction(seeds, {0.9}, Rs, from, 2, two);
  ASSERT_EQ(two.mu.size(), 1u);
  EXPECT_NEAR(two.mu[0].value, 0.3, 1e-12);
  EXPECT_NEAR(two.mu[0].error, 0.1, 1e-12);  // standard error of the mean of 0.2 and 0.4
  EXPECT_NE(two.note.find("from the 2 of 3 seeds"), std::string::npos);
  sliding_friction(seeds, {0.9}, Rs, from, 3, three);
  EXPECT_TRUE(std::isnan(three.mu[0].value));
}

}  // namespace
}  // namespace softpack
