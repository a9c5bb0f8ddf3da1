// Regression against the paper (issue 14; paper/paper.tex, "Reproduced vs published"): the
// archived paper profile of this release (data/archive/<release>/paper/, made by `make archive`;
// CI does not recompute it) against the published coefficients (experiments/published.yaml) and
// every claim of the paper's text.
//
// Published coefficients, with the tolerances of the issue, justified in paper/ from the
// seed-to-seed spread: Table 1 b within ±25 %, δ within ±35 %, a within a factor of 2; Table 2 b
// within ±35 %, a in the unit the evidence supports (N per degree of α: analysis/kt_unit.hpp)
// within a factor of 2. A coefficient the archive does not reproduce is an expected failure
// that asserts its measured gap: it is outside the tolerance, and its deviation is the one
// recorded below for the archive's release (to 1e-3 of it), so the test fails when the gap
// changes unnoticed — or when the coefficient comes within the tolerance (then it is a pass to
// record). A new release's archive needs its gaps recorded here.
//
// The paper's claims, on the archive's averages and fits: no force below δ; soft-soft softer
// than soft-solid at every Δn; both below Hertz's law for a solid sphere of radius Rs on a wall;
// the perpendicular tangential force zero within its standard errors; the prestrain (the
// parallel force at zero tangential deformation) shrinking as more seeds are averaged; kt
// growing with Δn; c = −a δ^b. And the archive is what it says: refitting its averages with its
// profile's fit reproduces its fits, and it was made by experiments/paper.yaml.
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

#include "analysis/fit_options.hpp"
#include "analysis/kt_unit.hpp"
#include "analysis/power_fit.hpp"
#include "config/profile.hpp"
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

// The release whose archive the gaps below were measured on. A test of another release's
// archive fails until its gaps are recorded (paper/paper.tex gives them with their causes).
constexpr const char* kRecordedRelease = "0.5.0";

struct Archive {
  fs::path dir;
  ConfigNode profile;
  std::map<std::string, FitEstimates> fits;
  std::map<std::string, AverageFile> averages;
};

const Archive& archive() {
  static const Archive a = [] {
    const fs::path dir = kSource / "data" / "archive" / release_version() / "paper";
    Archive out{dir, ConfigNode::load_file((dir / "profile.yaml").string()), {}, {}};
    for (const std::string& s : kScenes) {
      out.fits.emplace(s, read_fit_file((dir / "fits" / (s + ".json")).string()));
      out.averages.emplace(s, read_average_file((dir / "averages" / (s + ".h5")).string()));
    }
    return out;
  }();
  return a;
}

double published(const std::string& table, const std::string& scene, const std::string& key) {
  static const ConfigNode p = ConfigNode::load_file((kSource / "experiments" / "published.yaml").string());
  return p.at(table).at(scene).at(key).number();
}

// --- Published coefficients ----------------------------------------------------------------

enum class Tolerance { relative, factor };

struct Expectation {
  std::string table, scene, key;
  Tolerance kind;
  double tolerance;             // ±fraction (relative) or a factor
  std::optional<double> gap;    // recorded deviation (ours − paper)/|paper| of an expected failure
  double scale = 1.0;           // ours in the paper's unit = ours × scale
};

// The recorded gaps of release kRecordedRelease (nullopt: reproduced within the tolerance).
const std::vector<Expectation>& expectations() {
  const double per_degree = table::metres_per_degree(0.016);  // m of ht per degree of α (the paper's Rs)
  static const std::vector<Expectation> e{
      {"table1", "soft-solid", "a", Tolerance::factor, 2.0, std::nullopt},
      {"table1", "soft-solid", "b", Tolerance::relative, 0.25, std::nullopt},
      {"table1", "soft-solid", "delta", Tolerance::relative, 0.35, 0.59487},
      {"table1", "soft-soft", "a", Tolerance::factor, 2.0, -0.51203},
      {"table1", "soft-soft", "b", Tolerance::relative, 0.25, std::nullopt},
      {"table1", "soft-soft", "delta", Tolerance::relative, 0.35, 0.38535},
      {"table2", "soft-solid", "a", Tolerance::factor, 2.0, std::nullopt, per_degree},
      {"table2", "soft-solid", "b", Tolerance::relative, 0.35, std::nullopt},
      {"table2", "soft-soft", "a", Tolerance::factor, 2.0, -0.59070, per_degree},
      {"table2", "soft-soft", "b", Tolerance::relative, 0.35, -0.43289},
  };
  return e;
}

TEST(PublishedCoefficients, ArchiveIsOfTheRecordedRelease) {
  EXPECT_EQ(release_version(), kRecordedRelease)
      << "the gaps below were measured on archive " << kRecordedRelease << "; record this release's (paper/paper.tex)";
}

// One test per published coefficient, named <table>_<scene>_<key>_reproduced or
// ..._expected_failure, so that ctest lists which are which.
class Published : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Published, WithinItsToleranceOrAtItsRecordedGap) {
  const Expectation& e = expectations()[GetParam()];
  const FitEstimates& f = archive().fits.at(e.scene);
  ASSERT_TRUE(e.table == "table1" || f.tangential) << e.scene << ": no tangential fit in the archive";
  const auto& law = e.table == "table1" ? f.normal : *f.tangential;
  const double ours = law.at(e.key).value * e.scale, paper = published(e.table, e.scene, e.key);
  const double deviation = (ours - paper) / std::abs(paper);
  const bool within = e.kind == Tolerance::relative ? std::abs(deviation) <= e.tolerance
                                                    : ours / paper >= 1.0 / e.tolerance && ours / paper <= e.tolerance;
  const std::string tol = e.kind == Tolerance::relative ? fmt::format("±{:.0f} %", 100 * e.tolerance)
                                                        : fmt::format("a factor of {}", e.tolerance);
  if (!e.gap) {
    EXPECT_TRUE(within) << fmt::format("ours {:.6g}, paper {:.6g}: {:+.1f} %, outside {}", ours, paper, 100 * deviation, tol);
    return;
  }
  // Expected failure: not reproduced, by the recorded gap.
  EXPECT_FALSE(within) << fmt::format("ours {:.6g} is now within {} of the paper's {:.6g}: record it as reproduced", ours, tol,
                                      paper);
  EXPECT_NEAR(deviation, *e.gap, 1e-3 * std::max(1.0, std::abs(*e.gap)))
      << fmt::format("the gap to the paper changed: ours {:.6g}, paper {:.6g}, {:+.4g} (recorded {:+.4g})", ours, paper,
                     deviation, *e.gap);
  fmt::print("expected failure: {} {} {}: ours {:.4g}, paper {:.4g}, {:+.0f} % (tolerance {}; paper/paper.tex)\n", e.table,
             e.scene, e.key, ours, paper, 100 * deviation, tol);
}

INSTANTIATE_TEST_SUITE_P(PublishedCoefficients, Published, ::testing::Range<std::size_t>(0, expectations().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           const Expectation& e = expectations()[info.param];
                           std::string name = e.table + "_" + e.scene + "_" + e.key +
                                              (e.gap ? "_expected_failure" : "_reproduced");
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// --- The paper's claims ----------------------------------------------------------------------

// Eq. 7: F = 0 for Δn < δ. Every averaged force below the fitted δ should be zero within two of
// its standard errors, or below 10^-6 of the largest force (round-off: grains barely touching).
// Release 0.5.0 does not reproduce it: its dense packings carry a toe of force before the fitted
// δ, which Eq. 7 has not (paper/calibration.md, "At 0.75 the onset stops moving"). Expected
// failure asserting the gap: the largest such force, relative to the curve's largest, per scene.
TEST(PaperClaims, NoForceBelowDelta_expected_failure) {
  const std::map<std::string, double> recorded{{"soft-solid", 3.6475e-3}, {"soft-soft", 4.4998e-3}};
  for (const std::string& s : kScenes) {
    const AverageFile& a = archive().averages.at(s);
    const double delta = archive().fits.at(s).normal.at("delta").value;
    const double top = *std::max_element(a.Fn.begin(), a.Fn.end());
    double largest = 0.0;  // the largest force below δ that is not zero within the criterion, / top
    for (std::size_t k = 0; k < a.delta_n.size(); ++k)
      if (a.delta_n[k] < delta && !(std::abs(a.Fn[k]) <= 2.0 * a.Fn_stderr[k] || std::abs(a.Fn[k]) <= 1e-6 * top))
        largest = std::max(largest, std::abs(a.Fn[k]) / top);
    EXPECT_GT(largest, 0.0) << s << ": no force below delta now: record the claim as reproduced";
    EXPECT_NEAR(largest, recorded.at(s), 1e-3 * recorded.at(s))
        << fmt::format("{}: the largest force below delta changed: {:.5g} of the largest force", s, largest);
    fmt::print("expected failure: {}: a force of {:.2g} of the largest below delta = {:.3f} (paper/paper.tex)\n", s, largest,
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
// deformation": at every (Δn, α) the mean over the seeds should be within two of its standard
// errors of zero. (The points of one Δn share their normal state, so they are not independent,
// and no statistic over all of them is tested.) Release 0.5.0: the five points of soft-solid
// Δn = 0.2 lie 2.1–2.3 standard errors from zero, every other of the 14 (scene, Δn) groups
// within 2 — one group beyond 2σ among 14 happens by chance half the time (1 − 0.954^14), but
// the test is as specified: an expected failure asserting which group and how far.
TEST(PaperClaims, PerpendicularTangentialForceIsZeroWithinItsStandardErrors_expected_failure) {
  const std::set<std::pair<std::string, double>> recorded_groups{{"soft-solid", 0.2}};
  constexpr double kRecordedLargest = 2.3445;  // the largest |mean| / standard error
  std::set<std::pair<std::string, double>> failing;
  double largest = 0.0;
  for (const std::string& s : kScenes) {
    const TangentialSeeds t = tangential_seeds(s);
    ASSERT_GE(t.perpendicular.size(), 2u) << s;
    const double n = static_cast<double>(t.perpendicular.size());
    for (std::size_t k = 0; k < t.delta_n.size(); ++k) {
      double m = 0.0, v = 0.0;
      for (const auto& seed : t.perpendicular) m += seed[k];
      m /= n;
      for (const auto& seed : t.perpendicular) v += (seed[k] - m) * (seed[k] - m);
      const double se = std::sqrt(v / (n - 1.0) / n);
      if (std::abs(m) > 2.0 * se) failing.insert({s, std::round(t.delta_n[k] * 1e6) / 1e6});
      largest = std::max(largest, std::abs(m) / se);
    }
  }
  EXPECT_EQ(failing, recorded_groups) << "the (scene, delta_n) groups beyond two standard errors changed";
  EXPECT_NEAR(largest, kRecordedLargest, 1e-3 * kRecordedLargest) << "the largest |mean| / standard error changed";
  fmt::print("expected failure: Ft_perpendicular beyond 2 standard errors at soft-solid delta_n = 0.2 (largest {:.3f} se)\n",
             largest);
}

TEST(PaperClaims, PrestrainShrinksAsMoreSeedsAreAveraged) {
  // "a tangential force is existing even for zero deformation ... This prestrain averages out
  // the more simulations we average over": the parallel force at α = 0, averaged over k seeds,
  // its rms over Δn and over every set of k seeds, falls from k = 1 to 3 to all.
  for (const std::string& s : kScenes) {
    const TangentialSeeds t = tangential_seeds(s);
    const std::size_t n = t.parallel.size();
    ASSERT_GE(n, 3u) << s;
    std::vector<std::size_t> zero;
    for (std::size_t k = 0; k < t.alpha.size(); ++k)
      if (t.alpha[k] == 0.0) zero.push_back(k);
    ASSERT_FALSE(zero.empty()) << s << ": no alpha = 0 in the tangential grid";
    const auto rms_of_means = [&](std::size_t size) {
      double sum = 0.0;
      std::size_t count = 0;
      for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
        if (static_cast<std::size_t>(__builtin_popcount(mask)) != size) continue;
        for (std::size_t k : zero) {
          double m = 0.0;
          for (std::size_t i = 0; i < n; ++i)
            if (mask & (1u << i)) m += t.parallel[i][k];
          m /= static_cast<double>(size);
          sum += m * m, ++count;
        }
      }
      return std::sqrt(sum / static_cast<double>(count));
    };
    const double one = rms_of_means(1), three = rms_of_means(3), all = rms_of_means(n);
    EXPECT_LT(three, one) << s;
    EXPECT_LT(all, three) << s;
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

TEST(PaperClaims, CIsMinusADeltaToTheB) {
  // Eq. 7: δ = (−c/a)^(1/b), i.e. c = −a δ^b; Eq. 8: c = −a δ^b with Eq. 7's δ.
  for (const std::string& s : kScenes) {
    const FitEstimates& f = archive().fits.at(s);
    const double delta = f.normal.at("delta").value;
    const auto c_of = [&](const std::map<std::string, table::Estimate>& law) {
      return -law.at("a").value * std::pow(delta, law.at("b").value);
    };
    EXPECT_NEAR(f.normal.at("c").value, c_of(f.normal), 1e-9 * std::abs(f.normal.at("c").value)) << s;
    ASSERT_TRUE(f.tangential) << s;
    EXPECT_NEAR(f.tangential->at("c").value, c_of(*f.tangential), 1e-9 * std::abs(f.tangential->at("c").value)) << s;
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
