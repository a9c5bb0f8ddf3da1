// The packing generator (packing/): size distribution, geometry after insertion and growth,
// determinism, statistics and input validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "packing/generator.hpp"
#include "packing/insertion_grid.hpp"
#include "packing/power_law.hpp"
#include "packing/statistics.hpp"

namespace softpack {
namespace {

// Kolmogorov's limiting distribution: P(sqrt(N) D > lambda).
double kolmogorov_p(double D, std::size_t n) {
  const double sn = std::sqrt(static_cast<double>(n));
  const double lambda = (sn + 0.12 + 0.11 / sn) * D;
  double p = 0.0;
  for (int k = 1; k <= 100; ++k) p += 2.0 * ((k % 2) ? 1.0 : -1.0) * std::exp(-2.0 * k * k * lambda * lambda);
  return std::clamp(p, 0.0, 1.0);
}

double ks_statistic(std::vector<double> sample, const power_law::Law& law) {
  std::sort(sample.begin(), sample.end());
  double D = 0.0;
  const double n = static_cast<double>(sample.size());
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const double F = power_law::cdf(law, sample[i]);
    D = std::max({D, std::abs(F - static_cast<double>(i) / n), std::abs(static_cast<double>(i + 1) / n - F)});
  }
  return D;
}

TEST(PowerLaw, SampledRadiiFollowTheAnalyticDistribution) {
  const power_law::Law law{1e-3, 1e-2, 3.5};
  Random rng(42);
  std::vector<double> sample(100000);
  for (double& r : sample) r = power_law::sample(law, rng);
  // Kolmogorov-Smirnov at a fixed seed: the sample is accepted at the 1% level.
  const double p = kolmogorov_p(ks_statistic(sample, law), sample.size());
  EXPECT_GT(p, 0.01) << "p = " << p;
  // The same test rejects a neighbouring exponent: it can fail.
  const power_law::Law other{1e-3, 1e-2, 3.3};
  EXPECT_LT(kolmogorov_p(ks_statistic(sample, other), sample.size()), 1e-6);
  for (double r : sample) ASSERT_TRUE(r >= law.r_min && r <= law.r_max);
}

TEST(PowerLaw, MaximumLikelihoodRecoversTheExponent) {
  for (const double b : {2.5, 3.5, 4.5}) {
    const power_law::Law law{1e-3, 1e-2, b};
    Random rng(7);
    std::vector<double> sample(50000);
    for (double& r : sample) r = power_law::sample(law, rng);
    const power_law::Fit f = power_law::fit(sample);
    EXPECT_NEAR(f.b, b, 4.0 * f.b_error) << "b = " << b;
    EXPECT_LT(f.b_error, 0.05);
  }
}

TEST(PowerLaw, MeanCubeMatchesQuadrature) {
  const power_law::Law law{1e-3, 1e-2, 3.5};
  double sum = 0.0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) sum += std::pow(power_law::quantile(law, (k + 0.5) / n), 3);
  EXPECT_NEAR(power_law::mean_cube(law), sum / n, 1e-6 * sum / n);
}

// The insertion grid against brute force: a sphere inserted small and grown a hundredfold moves
// to the level that holds it, and queries (overlap, nearest gap) still find it and every other
// sphere exactly as a scan of all pairs does, on fine sparse levels (scanned sphere by sphere)
// and coarse ones alike.
TEST(InsertionGrid, GrownSpheresMoveUpAndQueriesMatchBruteForce) {
  const double r_min = 1e-5, r_max = 1e-2;  // Pi = 1000: eleven levels at ratio 2
  InsertionGrid grid(r_min, r_max, 2.0);
  Random rng(5);
  std::vector<Vec3> x;
  std::vector<double> r;
  for (int i = 0; i < 300; ++i) {
    x.push_back(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * 0.1);
    r.push_back(r_min * std::pow(r_max / r_min, rng.uniform()));
    grid.insert(x.back(), r.back());
  }
  const int grown = 7;
  const int before = grid.level(grown);
  r[grown] = std::min(100.0 * r[grown], r_max);
  grid.set_radius(grown, r[grown]);
  EXPECT_GT(grid.level(grown), before) << "the grown sphere moved up";
  EXPECT_EQ(grid.radius(grown), r[grown]);
  for (int q = 0; q < 2000; ++q) {
    const Vec3 y = q == 0 ? x[grown] : Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * 0.1;
    const double s = r_min * std::pow(r_max / r_min, rng.uniform());
    const double search = s * std::pow(2.0, static_cast<double>(q % 12));
    bool overlap = false;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < x.size(); ++j) {
      const double d = (y - x[j]).norm();
      overlap = overlap || d < s + r[j];
      const double g = d - s - r[j];
      if (g < search) gap = std::min(gap, g);
    }
    ASSERT_EQ(grid.overlaps(y, s), overlap) << "query " << q;
    ASSERT_EQ(grid.nearest_gap(y, s, -1, search), gap) << "query " << q;  // the same arithmetic: exact
  }
}

TEST(PackingStatistics, VolumeInsideBall) {
  const double pi = std::numbers::pi;
  EXPECT_DOUBLE_EQ(volume_inside_ball(0.1, 0.2, 1.0), 4.0 / 3.0 * pi * 0.008);  // inside
  EXPECT_EQ(volume_inside_ball(2.0, 0.5, 1.0), 0.0);                            // outside
  EXPECT_NEAR(volume_inside_ball(1.0, 1.0, 1.0), 5.0 / 12.0 * pi, 1e-14);       // symmetric lens
  // A sphere cut in half by a very large ball: half its volume.
  EXPECT_NEAR(volume_inside_ball(1e6, 1.0, 1e6) / (4.0 / 3.0 * pi), 0.5, 1e-5);
}

PackingParameters small_packing() {
  PackingParameters p;
  p.Rs = 0.016;
  p.r_max = 0.3 * p.Rs;
  p.polydispersity = 5;
  p.exponent = 3.5;
  p.beta = 1.0;
  p.trials = 300;
  p.shell_is_neighbour = true;
  p.level_ratio = 2.0;
  return p;
}

class Generated : public ::testing::TestWithParam<bool> {};  // param: shell_is_neighbour

TEST_P(Generated, NoOverlapInsideTheShellAndGrownSpheresTouchTheirNearestNeighbour) {
  PackingParameters p = small_packing();
  p.shell_is_neighbour = GetParam();
  const Packing pk = generate_packing(p, 3);
  const std::size_t n = pk.radii.size();
  ASSERT_GT(n, 200u);
  EXPECT_EQ(pk.sampled, n + pk.discarded);
  constexpr double kRelative = 1e-12;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_LE(pk.centres[i].norm() + pk.radii[i], p.Rs * (1 + kRelative)) << "sphere " << i << " crosses the shell";
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double gap = (pk.centres[i] - pk.centres[j]).norm() - pk.radii[i] - pk.radii[j];
      ASSERT_GE(gap, -kRelative * (pk.radii[i] + pk.radii[j])) << "spheres " << i << " and " << j << " overlap";
      nearest = std::min(nearest, gap);
    }
    if (p.shell_is_neighbour) nearest = std::min(nearest, p.Rs - pk.centres[i].norm() - pk.radii[i]);
    if (pk.radii[i] > pk.radii_inserted[i]) {  // grown: touches its nearest neighbour
      EXPECT_LE(std::abs(nearest), 1e-12 * p.Rs) << "grown sphere " << i << " is " << nearest << " m from its neighbour";
      ++touching;
    }
  }
  EXPECT_EQ(touching, pk.grown);
  EXPECT_GT(pk.grown, n / 2);
}

INSTANTIATE_TEST_SUITE_P(ShellAsNeighbour, Generated, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "ShellIsNeighbour" : "ShellIsNotNeighbour"; });

TEST(Generated, ShellAsNeighbourClosesTheGapToTheShell) {
  PackingParameters p = small_packing();
  p.shell_is_neighbour = true;
  const Packing pk_with = generate_packing(p, 5);
  const auto with = packing_statistics(pk_with.centres, pk_with.radii, p.Rs, p.r_max, 20);
  p.shell_is_neighbour = false;
  const Packing pk = generate_packing(p, 5);
  const auto without = packing_statistics(pk.centres, pk.radii, p.Rs, p.r_max, 20);
  EXPECT_EQ(with.min_shell_gap, 0.0);
  EXPECT_GT(without.min_shell_gap, 0.0);
  EXPECT_LT(with.depletion_length, without.depletion_length);
}

// packing.nearest_neighbour: centre. Every grown sphere touches the sphere whose centre is
// nearest (brute force over all pairs, to 1e-12 Rs) unless the shell stopped it first, and
// never crosses the shell; the reading differs from the surface one (overlaps appear), and the
// insertion (step 3) is the same, so the same spheres are placed at the same centres.
TEST(Generated, CentreReadingTouchesTheNearestCentre) {
  PackingParameters p = small_packing();
  const Packing surface = generate_packing(p, 4);
  p.nearest_neighbour = NearestNeighbour::centre;
  const Packing pk = generate_packing(p, 4);
  const std::size_t n = pk.radii.size();
  ASSERT_EQ(n, surface.radii.size());
  EXPECT_EQ(pk.centres, surface.centres);
  EXPECT_EQ(pk.radii_inserted, surface.radii_inserted);
  std::size_t overlapping = 0, grown = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double shell_gap = p.Rs - pk.centres[i].norm() - pk.radii[i];
    ASSERT_GE(shell_gap, -1e-12 * p.Rs) << "sphere " << i << " crosses the shell";
    // The nearest centre and the gap to it, with the radii after growth (each sphere grows
    // once, in order: a later sphere's growth cannot open a gap that an earlier one closed).
    std::size_t nearest = n;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double d = (pk.centres[i] - pk.centres[j]).norm();
      if (d < best) best = d, nearest = j;
      if (d < pk.radii[i] + pk.radii[j] - 1e-12 * p.Rs && j > i) ++overlapping;
    }
    ASSERT_LT(nearest, n);
    if (pk.radii[i] == pk.radii_inserted[i]) continue;
    ++grown;
    const double gap = best - pk.radii[i] - pk.radii[nearest];
    // Touches its nearest centre (or overlaps it, when that one grew later), unless the shell
    // stopped it first.
    if (std::abs(shell_gap) > 1e-12 * p.Rs) {
      EXPECT_LE(gap, 1e-12 * p.Rs) << "grown sphere " << i << " is " << gap << " m from its nearest centre's sphere";
    }
  }
  EXPECT_EQ(grown, pk.grown);
  EXPECT_GT(grown, n / 2);
  EXPECT_GT(overlapping, 0u) << "the centre reading gave the surface reading's packing";
  RecordProperty("overlapping_pairs", std::to_string(overlapping));
}

TEST(Generated, SameSeedSameBitsOtherSeedOtherPacking) {
  const PackingParameters p = small_packing();
  const Packing a = generate_packing(p, 11), b = generate_packing(p, 11), c = generate_packing(p, 12);
  ASSERT_EQ(a.radii.size(), b.radii.size());
  EXPECT_EQ(std::memcmp(a.centres.data(), b.centres.data(), a.centres.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.radii.data(), b.radii.data(), a.radii.size() * sizeof(double)), 0);
  EXPECT_TRUE(a.radii.size() != c.radii.size() || a.centres != c.centres);
}

// The paper says the fitted exponent is "roughly 3.5"; we accept 10% (the list is drawn with
// b = 3.5, then the insertion discards mostly small spheres and the growth inflates the small
// ones most, both of which flatten the distribution). The measured value is in the note.
TEST(Generated, PaperProfileExponentIsRoughly3p5) {
  const ConfigNode root = ConfigNode::load_file(SOFTPACK_SOURCE_DIR "/experiments/paper.yaml");
  const PackingProfile prof = parse_packing(root);
  const Packing pk = generate_packing(prof.parameters, 1);
  const auto s = packing_statistics(pk.centres, pk.radii, prof.parameters.Rs, prof.parameters.r_max, prof.profile_bins);
  RecordProperty("fitted_exponent", std::to_string(s.exponent.b));
  EXPECT_NEAR(s.exponent.b, 3.5, 0.35) << "fitted b = " << s.exponent.b << " +- " << s.exponent.b_error;
}

std::string packing_error(const std::string& replace_from, const std::string& replace_to) {
  std::string text = R"(profile: test
seeds: [1]
packing:
  Rs: 0.016
  r_max_over_Rs: 0.2
  polydispersity: 10
  exponent: 3.5
  beta: 1.0
  trials: 100
  shell_is_neighbour: true
  level_ratio: 2.0
  profile_bins: 20
)";
  if (!replace_from.empty()) {
    const auto at = text.find(replace_from);
    EXPECT_NE(at, std::string::npos);
    text.replace(at, replace_from.size(), replace_to);
  }
  try {
    parse_packing(ConfigNode::load_string(text, "profile.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PackingProfile, BadValuesNameTheKeyAndTheRange) {
  EXPECT_EQ(packing_error("", ""), "");
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      // The ranges are PackingParameters' validate()'s, placed at the key (line and column).
      {{"polydispersity: 10", "polydispersity: 1"}, ":6:19: packing.polydispersity: 1 is not allowed; allowed: 1 < Pi <= 1e6"},
      {{"exponent: 3.5", "exponent: 0.5"}, ":7:13: packing.exponent: 0.5 is not allowed; allowed: 1 < b <= 20"},
      {{"beta: 1.0", "beta: 0"}, ":8:9: packing.beta: 0 is not allowed; allowed: 0 < beta <= 100"},
      {{"trials: 100", "trials: 0"}, ":9:11: packing.trials: 0 is not allowed; allowed: 1 <= I <= 1e6"},
      {{"r_max_over_Rs: 0.2", "r_max_over_Rs: 1.0"}, ":5:18: packing.r_max_over_Rs: 1 is not allowed; allowed: 0 < r_max / Rs < 1"},
      {{"  beta: 1.0\n", ""}, "packing: missing required key 'beta'"},
      {{"trials: 100", "trials: many"}, "packing.trials: expected a number, got 'many'"},
      {{"beta: 1.0", "beta: 1.0\n  bta: 2"}, "packing.bta: unknown key; did you mean 'beta'?"},
      {{"beta: 1.0", "beta: 1.0\n  nearest_neighbour: middle"},
       "packing.nearest_neighbour: 'middle' is not allowed; allowed: surface (the smallest surface gap) or centre"},
  };
  for (const auto& [edit, expected] : cases) {
    const std::string msg = packing_error(edit.first, edit.second);
    EXPECT_NE(msg.find(expected), std::string::npos) << "got: " << msg << "\nexpected: " << expected;
    EXPECT_NE(msg.find("profile.yaml"), std::string::npos) << msg;
  }
}

TEST(PackingProfile, MalformedFileIsReported) {
  try {
    parse_packing(ConfigNode::load_string("packing: {Rs: [0.016", "broken.yaml"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.yaml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("malformed YAML"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace softpack
