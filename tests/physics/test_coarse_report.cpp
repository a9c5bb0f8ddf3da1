// The coarse-grain report's comparison (studies/coarse/report.hpp): where the two models' curves
// part, where the soft runs leave their laws, and two soft settings paired medium by medium.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coarse/compression.hpp"
#include "coarse/report.hpp"
#include "coarse/result_file.hpp"

namespace softpack {
namespace {

// Two seeds, the resolved curve sigma = 1000 strain (+-10 Pa between seeds), the soft one the
// same up to strain 0.05 and 50 % higher beyond: agreement up to 0.05, the stated speed-up.
TEST(CoarseGrain, TheComparisonFindsWhereTheCurvesPart) {
  std::vector<CoarseResult> resolved(2), soft(2);
  for (int s = 0; s < 2; ++s) {
    for (int k = 0; k <= 10; ++k) {
      const double e = 0.01 * k, noise = s ? 10.0 : -10.0;
      CurveRow row;
      row.strain = e, row.sigma_top = 1000.0 * e + noise, row.sigma_lateral = 0.3 * row.sigma_top;
      resolved[s].rows.push_back(row);
      row.sigma_top = (e > 0.055 ? 1500.0 : 1000.0) * e + noise;
      soft[s].rows.push_back(row);
    }
    resolved[s].seed = soft[s].seed = 900 + s;
    resolved[s].cpu_seconds = 100.0 * (s + 1), soft[s].cpu_seconds = 2.0;
  }
  const CoarseComparison c = compare_coarse(resolved, soft, 0.1, 0.0, 0.01);
  ASSERT_EQ(c.points.size(), 11u);
  EXPECT_NEAR(c.agreement_strain, 0.05, 1e-12);
  EXPECT_NEAR(c.points[3].sigma[0].mean, 30.0, 1e-9);
  EXPECT_NEAR(c.points[3].sigma[0].error, 10.0, 1e-9);  // two seeds at +-10: standard error 10
  EXPECT_NEAR(c.points[3].K0[1].mean, 0.3, 1e-12);
  EXPECT_NEAR(c.mean_speedup.mean, 75.0, 1e-9);
  EXPECT_TRUE(std::isnan(c.within_laws_strain)) << "the rows do not count the contacts beyond the laws";
  // Seed 900's soft run meets a contact beyond the laws' range from strain 0.07, seed 901's from 0.09:
  // within the laws up to 0.06 (the last row before the first).
  for (int s = 0; s < 2; ++s)
    for (CurveRow& row : soft[s].rows) row.beyond_range = row.strain > (s ? 0.085 : 0.065) ? 3 : 0, row.max_dn = 0.5;
  EXPECT_NEAR(strain_within_laws(soft[1].rows), 0.08, 1e-12);
  EXPECT_NEAR(compare_coarse(resolved, soft, 0.1, 0.0, 0.01).within_laws_strain, 0.06, 1e-12);
  soft[1].rows.front().beyond_range = 1;
  EXPECT_EQ(strain_within_laws(soft[1].rows), -1.0) << "beyond from the first row";
  EXPECT_EQ(compare_coarse(resolved, soft, 0.1, 0.0, 0.01).within_laws_strain, -1.0);
}

// Three media whose resolved stress differs by 60 % from one to the next; one setting's soft runs
// carry 0.5 of it on every medium, another's 0.6 (+-0.001 of it): by medium the shift is 0.1 with a
// small error, while the two ratios of means overlap within theirs. e* is the smaller of the two
// settings' within-laws strains; other resolved runs, or runs that do not count, are refused.
TEST(CoarseGrain, APairedShiftComparesTwoSoftSettingsMediumByMedium) {
  const auto runs = [](double carried, double wobble, double beyond_from) {
    std::vector<CoarseResult> resolved(3), soft(3);
    for (int s = 0; s < 3; ++s) {
      for (int k = 0; k <= 10; ++k) {
        const double e = 0.01 * k, res = 1000.0 * e * (1.0 + 0.6 * s);
        CurveRow row;
        row.strain = e, row.sigma_top = res;
        resolved[s].rows.push_back(row);
        row.sigma_top = (carried + (s == 1 ? wobble : 0.0)) * res;
        row.beyond_range = e > beyond_from ? 2 : 0, row.max_dn = 0.3;
        soft[s].rows.push_back(row);
      }
      resolved[s].seed = soft[s].seed = 910 + s;
      resolved[s].cpu_seconds = 10.0, soft[s].cpu_seconds = 1.0;
    }
    return std::pair{resolved, soft};
  };
  const auto [res_a, soft_a] = runs(0.5, 0.0, 0.085);
  const auto [res_b, soft_b] = runs(0.6, 0.001, 0.065);
  const CoarseComparison a = compare_coarse(res_a, soft_a, 0.1, 0.0, 0.01), b = compare_coarse(res_b, soft_b, 0.1, 0.0, 0.01);
  ASSERT_EQ(a.points[5].sigma_seed[0].size(), 3u);
  EXPECT_DOUBLE_EQ(a.points[5].sigma_seed[0][2], 1000.0 * 0.05 * 2.2);
  const std::optional<PairedShift> p = paired_shift(a, b);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->strain, 0.06, 1e-12) << "the smaller of 0.08 and 0.06";
  EXPECT_NEAR(p->q.mean, 0.1 + 0.001 / 3.0, 1e-12);
  EXPECT_NEAR(p->q.error, 0.001 / 3.0, 1e-12);  // values 0.1, 0.101, 0.1: s = 0.001/sqrt(3), se = s/sqrt(3)
  EXPECT_EQ(p->sign(), 1);
  EXPECT_NEAR(p->ratio[0].mean, 0.5, 1e-12);
  EXPECT_NEAR(p->ratio[1].mean, 0.6 + 0.001 * 1.6 / 4.8, 1e-12);
  EXPECT_GT(p->ratio[0].mean + 2.0 * p->ratio[0].error, p->ratio[1].mean - 2.0 * p->ratio[1].error)
      << "unpaired, the two ratios cannot tell the shift";
  EXPECT_EQ(paired_shift(b, a)->sign(), -1);
  EXPECT_EQ(paired_shift(a, a)->sign(), 0);
  std::string why;
  auto other = res_b;
  other[2].rows[4].sigma_top += 1.0;
  EXPECT_FALSE(paired_shift(a, compare_coarse(other, soft_b, 0.1, 0.0, 0.01), &why));
  EXPECT_NE(why.find("not the same resolved runs"), std::string::npos) << why;
  EXPECT_FALSE(paired_shift(a, compare_coarse(res_b, soft_b, 0.2, 0.0, 0.02), &why)) << "as many points, at other strains";
  EXPECT_NE(why.find("not the same recorded strains"), std::string::npos) << why;
  auto uncounted = soft_b;
  for (CurveRow& row : uncounted[0].rows) row.beyond_range = -1;
  EXPECT_FALSE(paired_shift(a, compare_coarse(res_b, uncounted, 0.1, 0.0, 0.01), &why));
  EXPECT_NE(why.find("does not count"), std::string::npos) << why;
}

}  // namespace
}  // namespace softpack
