// Tables 1 and 2 (analysis/fit_table.hpp): rounding of value ± error, the relative deviation,
// the Markdown of a known input (golden), "—" for a missing fit, and the LaTeX fragment.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/fit_table.hpp"
#include "analysis/kt_unit.hpp"
#include "core/types.hpp"

namespace {

using namespace softpack::table;
using softpack::kNaN;


TEST(FitTable, ValueAndErrorShareTheErrorsTwoSignificantDigits) {
  EXPECT_EQ(format_estimate_markdown({73.669, 1.234}), "73.7 ± 1.2");
  EXPECT_EQ(format_estimate_markdown({-0.035, 0.0012}), "-0.0350 ± 0.0012");
  EXPECT_EQ(format_estimate_markdown({2.799, 0.05}), "2.799 ± 0.050");
  EXPECT_EQ(format_estimate_markdown({1234.4, 56}), "1234 ± 56");
  EXPECT_EQ(format_estimate_markdown({12344, 678}), "12340 ± 680");
  EXPECT_EQ(format_estimate_markdown({3.4e5, 2.1e4}), "(3.40 ± 0.21)×10^5");
  EXPECT_EQ(format_estimate_markdown({-2.4e-5, 3.3e-6}), "(-2.40 ± 0.33)×10^-5");
  EXPECT_EQ(format_estimate_markdown({-0.00001, 0.02}), "0.000 ± 0.020");  // no "-0.000"
  // No error (exact or undefined): five significant digits.
  EXPECT_EQ(format_estimate_markdown({0.0024, kNaN}), "0.0024");
  EXPECT_EQ(format_estimate_markdown({73.66912, 0.0}), "73.669");
  EXPECT_EQ(format_estimate_markdown({2.4e-5, 0.0}), "2.4×10^-5");
  EXPECT_EQ(format_estimate_latex({73.669, 1.234}), "$73.7 \\pm 1.2$");
  EXPECT_EQ(format_estimate_latex({3.4e5, 2.1e4}), "$(3.40 \\pm 0.21)\\times10^{5}$");
}

TEST(FitTable, RelativeDeviation) {
  EXPECT_NEAR(relative_deviation_percent(50.0, 73.669), -32.12885, 1e-4);
  // Relative to |published|: a more negative c is a negative deviation.
  EXPECT_NEAR(relative_deviation_percent(-0.05, -0.035), -42.857, 1e-3);
  EXPECT_NEAR(relative_deviation_percent(-0.02, -0.035), 42.857, 1e-3);
  EXPECT_TRUE(std::isnan(relative_deviation_percent(1.0, 0.0)));
  EXPECT_EQ(format_deviation_markdown(-32.129), "-32.1%");
  EXPECT_EQ(format_deviation_markdown(10.754), "+10.8%");
  EXPECT_EQ(format_deviation_markdown(0.01), "0.0%");
  EXPECT_EQ(format_deviation_markdown(130.77), "+131%");
  // Beyond 1e5 %: two digits and a power of ten (a factor of a thousand and more).
  EXPECT_EQ(format_deviation_markdown(1.1354e6), "+1.1×10^6%");
  EXPECT_EQ(format_deviation_markdown(-6.3e5), "-6.3×10^5%");
  EXPECT_EQ(format_deviation_markdown(4.5e6), "+4.5×10^6%");
  EXPECT_EQ(format_deviation_markdown(kNaN), "—");
}

Table known_table1() {
  Column solid{"soft-solid",
               std::map<std::string, Estimate>{{"a", {50.0, 2.5}}, {"b", {3.1, 0.12}}, {"c", {-0.05, 0.004}}, {"delta", {0.15, 0.011}}},
               {{"a", 73.669}, {"b", 2.799}, {"c", -0.035}, {"delta", 0.065}}};
  Column soft{"soft-soft", std::nullopt, {{"a", 28.512}, {"b", 5.003}, {"c", -0.002}, {"delta", 0.148}}};
  return {"Table 1 (normal, Eq. 7)", table1_rows(), {solid, soft}};
}

TEST(FitTable, MarkdownOfAKnownInput) {
  const std::string expected =
      "| Table 1 (normal, Eq. 7) | soft-solid ours | soft-solid paper | soft-solid deviation | soft-soft ours | soft-soft paper "
      "| soft-soft deviation |\n"
      "|---|---:|---:|---:|---:|---:|---:|\n"
      "| a [N] | 50.0 ± 2.5 | 73.669 | -32.1% | — | 28.512 | — |\n"
      "| b | 3.10 ± 0.12 | 2.799 | +10.8% | — | 5.003 | — |\n"
      "| c [N] | -0.0500 ± 0.0040 | -0.035 | -42.9% | — | -0.002 | — |\n"
      "| δ | 0.150 ± 0.011 | 0.065 | +131% | — | 0.148 | — |\n";
  EXPECT_EQ(to_markdown(known_table1()), expected);
}

TEST(FitTable, Table2RowsAndMissingTangentialFit) {
  Column solid{"soft-solid", std::nullopt, {{"a", 0.740}, {"b", 2.100}, {"c", -0.0024}}};
  solid.published_text = {{"a", "0.740"}};  // the digits as published, when known
  Column soft{"soft-soft", std::map<std::string, Estimate>{{"a", {1.0, 0.1}}, {"b", {4.5, 0.3}}, {"c", {-0.0002, 0.00004}}},
              {{"a", 0.982}, {"b", 4.422}, {"c", -0.00021}}};
  const Table t{"Table 2 (tangential spring, Eq. 8)", table2_rows(), {solid, soft}};
  const std::string expected =
      "| Table 2 (tangential spring, Eq. 8) | soft-solid ours | soft-solid paper | soft-solid deviation | soft-soft ours | "
      "soft-soft paper | soft-soft deviation |\n"
      "|---|---:|---:|---:|---:|---:|---:|\n"
      "| a [N/m] | — | 0.740 | — | 1.00 ± 0.10 | 0.982 | +1.8% |\n"
      "| b | — | 2.1 | — | 4.50 ± 0.30 | 4.422 | +1.8% |\n"
      "| c [N/m] | — | -0.0024 | — | -0.000200 ± 0.000040 | -0.00021 | +4.8% |\n";
  EXPECT_EQ(to_markdown(t), expected);
}

TEST(FitTable, LatexIsABooktabsTabularWithTheProvenanceAsComments) {
  const std::string tex = to_latex(known_table1(), "Table 1 (normal, Eq. 7)\nsoftpack-table 0.1.0; fits: x.json");
  EXPECT_EQ(tex.rfind("% Table 1 (normal, Eq. 7)\n% softpack-table 0.1.0; fits: x.json\n\\begin{tabular}{lrrrrrr}\n\\toprule\n", 0),
            0u)
      << tex;
  EXPECT_NE(tex.find(" & \\multicolumn{3}{c}{soft-solid} & \\multicolumn{3}{c}{soft-soft} \\\\\n"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\cmidrule(lr){2-4} \\cmidrule(lr){5-7}\n"), std::string::npos) << tex;
  EXPECT_NE(tex.find("$a$ [N] & $50.0 \\pm 2.5$ & $73.669$ & $-32.1$\\,\\% & --- & $28.512$ & --- \\\\\n"), std::string::npos)
      << tex;
  EXPECT_NE(tex.find("$\\delta$ & $0.150 \\pm 0.011$"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\bottomrule\n\\end{tabular}\n"), std::string::npos) << tex;
  EXPECT_EQ(tex.find("\\caption"), std::string::npos);
}

}  // namespace

// --- The unit of Table 2 (analysis/kt_unit.hpp) ------------------------------------------------

TEST(KtUnit, AKtPrintedPerDegreeIsRecognisedByItsRatioToFn) {
  // Ours: the paper's laws, with kt in N per metre of ht: kt_paper [N/deg] / (pi Rs / 180 m/deg),
  // and both forces ten times the paper's (a stiffer soft-particle of the same shape of response).
  using namespace softpack::table;
  const double Rs = 0.016, per_degree = std::numbers::pi * Rs / 180.0;
  const PublishedLaw Fn{73.669, 2.799, -0.035, 0.065}, kt{0.740, 2.100, -0.0024, 0.065};
  std::vector<double> dn, F, Fe, kdn, k, ke;
  for (double x : {0.2, 0.3, 0.4, 0.5}) {
    dn.push_back(x), F.push_back(10 * Fn(x)), Fe.push_back(0.01 * Fn(x));
    kdn.push_back(x), k.push_back(10 * kt(x) / per_degree), ke.push_back(0.01 * kt(x) / per_degree);
  }
  const auto readings = kt_readings(Rs);
  const KtUnitScene s = kt_unit_scene("soft-solid", dn, F, Fe, kdn, k, ke, Fn, kt, readings, 3.0);
  ASSERT_EQ(s.points.size(), 4u);
  std::size_t degree = 0;
  while (readings[degree].unit != "N/deg") ++degree;
  EXPECT_NEAR(std::exp(s.mean_log_q[degree]), 1.0, 1e-12);
  for (std::size_t r = 0; r < readings.size(); ++r) {
    if (r != degree) {
      EXPECT_GT(std::abs(s.mean_log_q[r]), 1.0) << readings[r].unit;  // off by e or more
    }
  }
  EXPECT_NE(kt_unit_markdown({s}, readings).find("Closest to 1 on soft-solid: per degree of alpha (N/deg)"), std::string::npos);
  // A point whose kt is within three standard errors of zero is listed, not counted.
  ke[0] = k[0] / 2.5;
  const KtUnitScene t = kt_unit_scene("soft-solid", dn, F, Fe, kdn, k, ke, Fn, kt, readings, 3.0);
  EXPECT_FALSE(t.points[0].established);
  EXPECT_TRUE(t.points[1].established);
}
