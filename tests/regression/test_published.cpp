// Regression against the paper (issues 14, 29; paper/paper.tex, "Reproduced vs published"): the
// archived paper profile of this release (data/archive/<release>/paper/, made by `make archive`;
// CI does not recompute the sweeps) against the published coefficients
// (experiments/published.yaml) and every claim of the paper's text.
//
// One source for the verdict: the archive's tables/verdict.json, written by softpack-table from
// the preregistered criteria (experiments/criteria.yaml, archived beside it). Each coefficient's
// test recomputes the verdict with the current code from the archive's fits and averages and its
// criteria, and asserts it is the archived one (status and deviation): a change of code that
// changes a verdict fails here until the release is re-archived. A coefficient not reproduced is
// an expected failure: it prints its measured gap (from the data, never typed here) and fails when
// the coefficient comes within its tolerance, so that the report is updated.
//
// The paper's claims, on the archive's averages and fits: no force below δ; soft-soft softer
// than soft-solid at every Δn; both below Hertz's law for a solid sphere of radius Rs on a wall;
// the perpendicular tangential force and the prestrain (the parallel force at zero tangential
// deformation) averaging out over independent seeds (a test that a common offset fails); kt
// growing with Δn; Eq. 7 describing the averages within their errors. And the archive is what it
// says: refitting its averages with its profile's fit reproduces its fits, and it was made by
// experiments/paper.yaml. tests/regression/test_recompute.sh runs the programs themselves on the
// archive's per-seed results.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <fstream>

#include "analysis/fit_options.hpp"
#include "analysis/fit_selection.hpp"
#include "analysis/kt_unit.hpp"
#include "analysis/verdict.hpp"
#include "analysis/power_fit.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/version.hpp"
#include "formats/average_file.hpp"
#include "formats/fit_file.hpp"
#include "formats/sweep_file.hpp"

namespace softpack {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = SOFTPACK_SOURCE_DIR;
const std::vector<std::string> kScenes{"soft-solid", "soft-soft"};

struct Archive {
  fs::path dir;
  ConfigNode profile;
  std::map<std::string, FitEstimates> fits;
  std::map<std::string, AverageFile> averages;
  nlohmann::json verdict;  // tables/verdict.json
};

const Archive& archive() {
  static const Archive a = [] {
    const fs::path dir = kSource / "data" / "archive" / release_version() / "paper";
    Archive out{dir, ConfigNode::load_file((dir / "profile.yaml").string()), {}, {}, {}};
    for (const std::string& s : kScenes) {
      out.fits.emplace(s, read_fit_file((dir / "fits" / (s + ".json")).string()));
      out.averages.emplace(s, read_average_file((dir / "averages" / (s + ".h5")).string()));
    }
    std::ifstream in(dir / "tables" / "verdict.json");
    if (!in) throw std::runtime_error((dir / "tables" / "verdict.json").string() + ": missing (make archive from a 0.7.0 tree)");
    out.verdict = nlohmann::json::parse(in);
    return out;
  }();
  return a;
}

double published(const std::string& table, const std::string& scene, const std::string& key) {
  static const ConfigNode p = ConfigNode::load_file((kSource / "experiments" / "published.yaml").string());
  return p.at(table).at(scene).at(key).number();
}

// --- Published coefficients ----------------------------------------------------------------

// The verdict recomputed by the current code from the archive (its fits, averages, criteria).
const verdict::Verdict& recomputed() {
  static const verdict::Verdict v = [] {
    const fs::path dir = archive().dir;
    const ConfigNode criteria = ConfigNode::load_file((dir / "criteria.yaml").string());
    std::vector<verdict::SceneInput> in;
    for (const std::string& s : kScenes) {
      const FitEstimates& f = archive().fits.at(s);
      const AverageFile& a = archive().averages.at(s);
      verdict::SceneInput x;
      x.scene = s, x.normal = f.normal, x.tangential = f.tangential;
      if (f.jackknife && f.jackknife->done) x.jackknife = f.jackknife->covariance;
      x.delta_n = a.delta_n, x.Fn = a.Fn, x.Fn_stderr = a.Fn_stderr;
      x.kt_delta_n = a.kt_delta_n, x.kt = a.kt, x.kt_stderr = a.kt_stderr;
      x.paper_normal = {published("table1", s, "a"), published("table1", s, "b"), published("table1", s, "c"),
                        published("table1", s, "delta")};
      x.paper_tangential = {published("table2", s, "a"), published("table2", s, "b"), published("table2", s, "c"),
                            published("table1", s, "delta")};
      in.push_back(x);
    }
    return verdict::judge(in, verdict::parse_criteria(criteria), archive().profile.at("packing").at("Rs").number());
  }();
  return v;
}

// The ten coefficients, in the verdict's order (per scene: Table 1 a, b, δ; Table 2 a, b).
struct Coefficient {
  std::string table, scene, key;
};
const std::vector<Coefficient>& coefficients() {
  static const std::vector<Coefficient> c = [] {
    std::vector<Coefficient> out;
    for (const std::string& s : kScenes)
      for (const auto& [t, k] : std::vector<std::pair<std::string, std::string>>{
               {"table1", "a"}, {"table1", "b"}, {"table1", "delta"}, {"table2", "a"}, {"table2", "b"}})
        out.push_back({t, s, k});
    return out;
  }();
  return c;
}

class Published : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Published, TheArchivedVerdictIsTheCodesAndReproducedOrAnExpectedFailure) {
  const Coefficient& c = coefficients()[GetParam()];
  const nlohmann::json* archived = nullptr;
  for (const auto& l : archive().verdict.at("lines"))
    if (l.at("table") == c.table && l.at("scene") == c.scene && l.at("key") == c.key) archived = &l;
  ASSERT_NE(archived, nullptr) << "verdict.json has no line for " << c.table << " " << c.scene << " " << c.key;
  const verdict::Line* now = nullptr;
  for (const verdict::Line& l : recomputed().lines)
    if (l.table == c.table && l.scene == c.scene && l.key == c.key) now = &l;
  ASSERT_NE(now, nullptr);
  const std::string status = archived->at("status").get<std::string>();
  EXPECT_EQ(now->status, status) << "the code's verdict differs from the archive's: re-archive (make archive)";
  if (archived->at("deviation").is_number()) {
    const double d = archived->at("deviation").get<double>();
    EXPECT_NEAR(now->deviation, d, 1e-9 * std::max(1.0, std::abs(d))) << "the deviation from the paper changed";
  }
  if (status == "reproduced") return;
  // Expected failure: the measured gap, from the data.
  fmt::print("expected failure: {} {} {}: {} (ours {:.4g}, paper {:.4g}, {:+.0f} %, tolerance {}; paper/paper.tex)\n", c.table,
             c.scene, c.key, status, now->ours, now->paper, 100 * now->deviation, now->tolerance);
}

INSTANTIATE_TEST_SUITE_P(PublishedCoefficients, Published, ::testing::Range<std::size_t>(0, 10),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           const Coefficient& c = coefficients()[info.param];
                           std::string name = c.table + "_" + c.scene + "_" + c.key;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(PublishedCoefficients, TheReportsVerdictCountIsTheArchives) {
  EXPECT_EQ(recomputed().reproduced, archive().verdict.at("reproduced").get<std::size_t>());
  EXPECT_EQ(recomputed().unit.selected, archive().verdict.at("unit").at("selected").get<std::string>());
  EXPECT_EQ(recomputed().unit.passed, archive().verdict.at("unit").at("passed").get<bool>());
}

// --- The paper's claims ----------------------------------------------------------------------

// Eq. 7: F = 0 for Δn < δ. Every averaged force below the fitted δ should be zero within two of
// its standard errors, or below 10^-6 of the largest force (round-off: grains barely touching).
// Dense packings carry a toe of force before the fitted δ, which Eq. 7 has not
// (paper/calibration.md): when the archive shows one, the test prints it, the largest such force
// relative to the curve's largest (an expected failure; it fails when the toe is gone).
TEST(PaperClaims, NoForceBelowDelta) {
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    const double delta = archive().fits.at(s).normal.at("delta").value;
    const double top = *std::max_element(a.Fn.begin(), a.Fn.end());
    double largest = 0.0;  // the largest force below δ that is not zero within the criterion, / top
    for (std::size_t k = 0; k < a.delta_n.size(); ++k)
      if (a.delta_n[k] < delta && !(std::abs(a.Fn[k]) <= 2.0 * a.Fn_stderr[k] || std::abs(a.Fn[k]) <= 1e-6 * top))
        largest = std::max(largest, std::abs(a.Fn[k]) / top);
    double archived = -1.0;
    for (const auto& c : archive().verdict.at("curves"))
      if (c.at("scene") == s) archived = c.at("force_below_delta").get<double>();
    EXPECT_NEAR(largest, archived, 1e-12) << s << ": the force below delta differs from the archived verdict's";
    const bool toe = largest > 0.0;
    if (toe)
      fmt::print("expected failure: {}: a force of {:.2g} of the largest below delta = {:.4f} (paper/paper.tex)\n", s, largest,
                 delta);
  }
}

TEST(PaperClaims, SoftSoftIsSofterThanSoftSolidAtEveryDeltaN) {
  const AverageFile &solid = archive().averages.at("soft-solid"), &soft = archive().averages.at("soft-soft");
  ASSERT_EQ(solid.delta_n, soft.delta_n);
  // Forces below 1e-6 of soft-solid's largest are round-off (grains touching at Δn = 0): zero.
  const double zero = 1e-6 * *std::max_element(solid.Fn.begin(), solid.Fn.end());
  for (std::size_t k = 0; k < solid.delta_n.size(); ++k)
    EXPECT_TRUE(soft.Fn[k] <= zero || soft.Fn[k] <= solid.Fn[k] + 2.0 * std::hypot(soft.Fn_stderr[k], solid.Fn_stderr[k]))
        << "delta_n = " << solid.delta_n[k] << ": soft-soft " << soft.Fn[k] << ", soft-solid " << solid.Fn[k];
}

TEST(PaperClaims, BothBelowHertzForASolidSphereOfRadiusRsOnAWall) {
  // Eq. 3 with R12 = Rs (a wall) and D = 3/4 · 2(1 − ν²)/E (one material).
  const ConfigNode m = archive().profile.at("material");
  const double E = m.at("E").number(), nu = m.at("nu").number();
  const double Rs = archive().profile.at("packing").at("Rs").number();
  const double D = 0.75 * 2.0 * (1.0 - nu * nu) / E;
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    for (std::size_t k = 0; k < a.delta_n.size(); ++k) {
      const double h = a.delta_n[k] * Rs, hertz = std::sqrt(Rs) * std::pow(h, 1.5) / D;
      if (a.delta_n[k] > 0.0) {
        EXPECT_LT(a.Fn[k] + 2.0 * a.Fn_stderr[k], hertz) << s << " delta_n = " << a.delta_n[k];
      }
    }
  }
}

// The tangential results of every seed of a scene: (Δn, α) -> per-seed Ft.
struct TangentialSeeds {
  std::vector<double> delta_n, alpha;
  std::vector<std::vector<double>> parallel, perpendicular;  // [seed][point]
};
TangentialSeeds tangential_seeds(const std::string& scene) {
  TangentialSeeds t;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(archive().dir / "tangential"))
    if (e.path().extension() == ".h5" && e.path().filename().string().rfind(scene + "-seed-", 0) == 0) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& p : files) {
    const SweepResults r = read_sweep_results_file(p.string());
    if (t.delta_n.empty()) t.delta_n = r.delta_n, t.alpha = r.alpha_deg;
    t.parallel.push_back(r.Ft_parallel);
    t.perpendicular.push_back(r.Ft_perpendicular);
  }
  return t;
}

// "the tangential force in the perpendicular direction ... is, on average, unaffected by the
// deformation", and "a tangential force is existing even for zero deformation ... This prestrain
// averages out the more simulations we average over": over independent seeds the mean of each
// should be zero within its standard error at every point (verdict::zero_mean_test: Student's t
// per point, Bonferroni over the points, p >= 0.01). A common offset of every seed fails it
// (Criteria.APrestrainThatAveragesOutPassesAndACommonOffsetFails).
TEST(PaperClaims, PerpendicularTangentialForceAveragesOut) {
  for (const std::string& s : kScenes) {
    const TangentialSeeds t = tangential_seeds(s);
    ASSERT_GE(t.perpendicular.size(), 3u) << s;
    std::vector<std::vector<double>> rows(t.delta_n.size());
    for (const auto& seed : t.perpendicular)
      for (std::size_t k = 0; k < seed.size(); ++k) rows[k].push_back(seed[k]);
    const verdict::ZeroMeanTest z = verdict::zero_mean_test(rows);
    EXPECT_GE(z.p, 0.01) << fmt::format("{}: the perpendicular force does not average out: largest |t| = {:.3g} over {} points, "
                                        "p = {:.3g}", s, z.largest_t, z.points, z.p);
    fmt::print("{}: perpendicular force: largest |mean/se| {:.3g} over {} points, p = {:.3g}\n", s, z.largest_t, z.points, z.p);
  }
}

TEST(PaperClaims, PrestrainAveragesOut) {
  for (const std::string& s : kScenes) {
    const TangentialSeeds t = tangential_seeds(s);
    ASSERT_GE(t.parallel.size(), 3u) << s;
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < t.alpha.size(); ++k) {
      if (t.alpha[k] != 0.0) continue;
      rows.emplace_back();
      for (const auto& seed : t.parallel) rows.back().push_back(seed[k]);
    }
    ASSERT_FALSE(rows.empty()) << s << ": no alpha = 0 in the tangential grid";
    const verdict::ZeroMeanTest z = verdict::zero_mean_test(rows);
    EXPECT_GE(z.p, 0.01) << fmt::format("{}: the prestrain does not average out: largest |t| = {:.3g} over {} points, p = {:.3g}",
                                        s, z.largest_t, z.points, z.p);
    fmt::print("{}: prestrain: largest |mean/se| {:.3g} over {} points, p = {:.3g}\n", s, z.largest_t, z.points, z.p);
  }
}

TEST(PaperClaims, KtGrowsWithDeltaN) {
  // Over the Δn where kt is established (at least two standard errors above zero), each kt is
  // above the previous one within their standard errors.
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    ASSERT_TRUE(a.has_kt) << s;
    std::optional<std::size_t> last;
    std::size_t established = 0;
    for (std::size_t k = 0; k < a.kt_delta_n.size(); ++k) {
      if (!(a.kt[k] >= 2.0 * a.kt_stderr[k])) continue;
      ++established;
      if (last) {
        EXPECT_GE(a.kt[k] + 2.0 * std::hypot(a.kt_stderr[k], a.kt_stderr[*last]), a.kt[*last])
            << s << ": kt(" << a.kt_delta_n[k] << ") = " << a.kt[k] << " below kt(" << a.kt_delta_n[*last] << ") = " << a.kt[*last];
      }
      last = k;
    }
    // Soft-solid's kt is established over most of its grid; soft-soft's begins at its last points.
    if (s == "soft-solid") {
      EXPECT_GE(established, 3u);
    }
  }
}

// "The results are fitted with" Eq. 7: the law should describe the averages within their
// errors. Judged as the criteria judge every fit (chi2/dof over every point and the runs test of
// the residuals, power_fit.hpp) — recomputed here and equal to the archived fit file's; when it
// is not adequate the test prints by how much (an expected failure of the paper's form, reported
// in paper/paper.tex).
TEST(PaperClaims, Eq7DescribesTheAveragesWithinTheirErrors) {
  const ConfigNode criteria = ConfigNode::load_file((archive().dir / "criteria.yaml").string());
  const fit::FitCriteria c = fit::parse_fit_criteria(criteria);
  const fit::FitSection section = fit::parse_fit_section(archive().profile);
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    const fit::PowerLawFit n = fit::fit_normal_law(a.delta_n, a.Fn, a.Fn_stderr, section.options_for(s));
    const fit::Judgement j = fit::judge_normal_law(n, a.delta_n, a.Fn, a.Fn_stderr, c.sigma_floor, c.delta_n_max);
    const FitEstimates& f = archive().fits.at(s);
    ASSERT_TRUE(f.judged) << s << ": the archived fit was not judged (softpack-fit --criteria)";
    EXPECT_NEAR(j.chi2_per_dof, f.judged->chi2_per_dof, 1e-9 * j.chi2_per_dof) << s;
    const bool adequate = j.chi2_per_dof <= c.chi2_per_dof_max && std::abs(j.runs_z) <= c.runs_z_max;
    if (!adequate)
      fmt::print("expected failure: {}: Eq. 7 does not describe the averages within their errors: chi2/dof {:.3g} (at most {:g}), "
                 "runs z {:.3g} (|z| at most {:g})\n",
                 s, j.chi2_per_dof, c.chi2_per_dof_max, j.runs_z, c.runs_z_max);
  }
}

// --- The archive is what it says ---------------------------------------------------------------

TEST(ArchiveConsistency, RefittingTheArchivedAveragesReproducesTheArchivedFits) {
  const fit::FitSection section = fit::parse_fit_section(archive().profile);
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    const fit::FitOptions options = section.options_for(s);
    const fit::PowerLawFit n = fit::fit_normal_law(a.delta_n, a.Fn, a.Fn_stderr, options);
    const FitEstimates& f = archive().fits.at(s);
    for (const auto& [key, value] : std::map<std::string, double>{{"a", n.a}, {"b", n.b}, {"c", n.c}, {"delta", n.delta}})
      EXPECT_NEAR(value, f.normal.at(key).value, 1e-10 * std::abs(value)) << s << " normal " << key;
    const fit::PowerLawFit t = fit::fit_tangential_law(a.kt_delta_n, a.kt, a.kt_stderr, n.delta, options);
    ASSERT_TRUE(f.tangential) << s;
    for (const auto& [key, value] : std::map<std::string, double>{{"a", t.a}, {"b", t.b}, {"c", t.c}})
      EXPECT_NEAR(value, f.tangential->at(key).value, 1e-10 * std::abs(value)) << s << " tangential " << key;
  }
}

TEST(ArchiveConsistency, ArchiveWasMadeByTheCurrentPaperProfile) {
  const ConfigNode current = ConfigNode::load_file((kSource / "experiments" / "paper.yaml").string());
  std::vector<std::string> differ;
  for (const std::string& section : profile_sections())
    if (section != "description" && section != "watchdog" && section_text(archive().profile, section) != section_text(current, section))
      differ.push_back(section);
  EXPECT_TRUE(differ.empty()) << "experiments/paper.yaml differs from the archive's profile in: " << fmt::format("{}", fmt::join(differ, ", "))
                              << " (rerun and archive it: make archive)";
}

}  // namespace
}  // namespace softpack
