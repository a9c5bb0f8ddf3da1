// The coarse-grain medium with nested soft-particles (coarse/medium.hpp, docs/nested.md): the
// sites' packings are level packings, their own sites' contents go down to the last level, and
// both models hold the same medium — the resolved one every grain at every level inside nested
// free shells, the soft one a soft-particle of the mass of all that.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "coarse/compression.hpp"
#include "coarse/medium_file.hpp"
#include "coarse/resolved_estimate.hpp"
#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "measure/content_scene.hpp"
#include "sim/simulation.hpp"
#include "support/coarse_tiny.hpp"

namespace softpack {
namespace nested_medium_test {

const CoarseGrainSettings& nested() { return testing::coarse_grain_nested_tiny(); }

const Medium& medium() {
  static const Medium m = build_medium(nested(), 901);
  return m;
}

SoftParticleLaws laws() { return soft_particle_laws(read_law_file(nested().laws), nested().laws); }

double ball(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// The sites stand for the two levels below the first decade: the target is the power law's volume
// down to the last level's grains (r_max / Π²), and the packings' volume counts every level.
TEST(NestedMedium, TheSitesHoldLevelPackingsAndTheVolumeOfEveryLevel) {
  const Medium& m = medium();
  const CoarseGrainSettings& s = nested();
  ASSERT_EQ(m.levels, 2);
  ASSERT_GE(m.sites.size(), 1u);
  ASSERT_EQ(m.inner_sites.size(), m.sites.size());
  ASSERT_EQ(m.contents.size(), m.sites.size());
  EXPECT_NEAR(m.inner_radius, s.packing.Rs / s.packing.polydispersity, 1e-15);
  std::size_t inner = 0;
  double V = 0.0;
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    ASSERT_EQ(m.contents[k].size(), m.inner_sites[k].size());
    inner += m.inner_sites[k].size();
    for (double r : m.packings[k].radii) V += ball(r);
    for (const SiteContent& c : m.contents[k]) {
      EXPECT_TRUE(c.sites.empty()) << "the last level holds grains only";
      V += c.solid_volume();
    }
  }
  EXPECT_GE(inner, 1u) << "no site of the tiny medium holds a soft-particle of level 1: the test tests nothing";
  EXPECT_NEAR(m.packings_volume, V, 1e-12 * V);
  const double r1 = s.r_min_over_Rs * m.Rs, r2max = s.packing.r_max, r2min = r2max / std::pow(s.packing.polydispersity, 2);
  EXPECT_NEAR(m.target_volume, m.grains_volume * (std::sqrt(r2max) - std::sqrt(r2min)) / (std::sqrt(10 * r1) - std::sqrt(r1)),
              1e-12 * m.target_volume);
  const Medium again = build_medium(nested(), 901);
  EXPECT_EQ(again.inner_sites, m.inner_sites);
  EXPECT_EQ(again.contents.back().back().level.grains.radii, m.contents.back().back().level.grains.radii);
}

// Resolved: each site's grains and shell (shell k is site k's, 5 % of every grain inside it), then
// its sites' contents in free shells whose parent is the site's body; soft: one soft-particle of
// the site's whole mass resolved — the same mass in both models, site by site.
TEST(NestedMedium, BothModelsHoldTheSameMassSiteBySite) {
  const Medium& m = medium();
  const SceneDef a = medium_scene(nested(), m, CoarseModel::resolved, laws());
  const SceneDef b = medium_scene(nested(), m, CoarseModel::soft, laws());
  const double rho = nested().simulation.material.density;
  const std::vector<int> body = sphere_bodies(m, CoarseModel::resolved);
  ASSERT_EQ(body.size(), a.particles.size());
  ASSERT_EQ(sphere_bodies(m, CoarseModel::soft).size(), b.particles.size());
  const std::size_t grains = m.grain_x.size(), sites = m.sites.size();
  std::vector<double> resolved(sites, 0.0);  // each site's spheres and shells
  for (std::size_t i = 0; i < a.particles.size(); ++i)
    if (body[i] >= static_cast<int>(grains)) resolved[static_cast<std::size_t>(body[i]) - grains] += rho * ball(a.particles[i].r);
  // The bodies of the inner shells lead back to their site: the site's own body (k) is their root.
  std::size_t inner_shells = 0;
  for (std::size_t j = 0; j < a.shells.size(); ++j) {
    const ShellDef& sh = a.shells[j];
    ASSERT_TRUE(sh.mass.has_value());
    if (j < sites) {
      EXPECT_EQ(sh.body, static_cast<int>(j));
      EXPECT_EQ(sh.centre, m.sites[j]);
      EXPECT_EQ(sh.radius, m.Rs);
      EXPECT_EQ(sh.parent, kNoBody);
      resolved[j] += *sh.mass;
      continue;
    }
    ++inner_shells;
    EXPECT_EQ(sh.radius, m.inner_radius);
    int root = sh.parent;
    for (int guard = 0; root >= static_cast<int>(sites) && guard < 100; ++guard)
      for (const ShellDef& up : a.shells)
        if (up.body == root) root = up.parent;
    ASSERT_GE(root, 0);
    ASSERT_LT(root, static_cast<int>(sites));
    resolved[static_cast<std::size_t>(root)] += *sh.mass;
  }
  std::size_t contents = 0;
  for (const auto& cs : m.contents)
    for (const SiteContent& c : cs) contents += 1 + c.shells();
  EXPECT_EQ(inner_shells, contents);
  for (std::size_t k = 0; k < sites; ++k) {
    double inside = 0.0;
    for (double r : m.packings[k].radii) inside += rho * ball(r);
    for (const SiteContent& c : m.contents[k]) inside += rho * c.solid_volume();
    EXPECT_NEAR(*a.shells[k].mass, 0.05 * inside, 1e-12 * inside) << "site " << k << "'s shell weighs 5 % of every grain inside it";
    const ParticleDef& soft = b.particles[grains + k];
    ASSERT_TRUE(soft.soft);
    EXPECT_NEAR(*soft.mass, resolved[k], 1e-12 * resolved[k]) << "site " << k;
  }
}

// The medium file keeps the sites' own sites; their contents are made again from the seeds, for
// the settings' levels only; a scene of a nested medium without them is refused.
TEST(NestedMedium, TheFileKeepsTheSitesSitesAndTheContentsComeBackFromTheSeeds) {
  const Medium& m = medium();
  const std::string dir = ::testing::TempDir() + "/nested-medium";
  std::filesystem::create_directories(dir);
  write_medium_file(dir + "/medium.h5", MediumFile{m, 901, nested().medium_text, "test", {}});
  Medium back = read_medium_file(dir + "/medium.h5").medium;
  EXPECT_EQ(back.levels, 2);
  EXPECT_EQ(back.inner_radius, m.inner_radius);
  EXPECT_EQ(back.inner_sites, m.inner_sites);
  EXPECT_TRUE(back.contents.empty());
  EXPECT_THROW(medium_scene(nested(), back, CoarseModel::soft, laws()), InputError);
  EXPECT_THROW(medium_contents(testing::coarse_grain_tiny(), back), InputError);  // one level: not this medium
  medium_contents(nested(), back);
  ASSERT_EQ(back.contents.size(), m.contents.size());
  for (std::size_t k = 0; k < m.contents.size(); ++k)
    for (std::size_t j = 0; j < m.contents[k].size(); ++j)
      EXPECT_EQ(back.contents[k][j].level.grains.centres, m.contents[k][j].level.grains.centres);
  // A medium of one level has none of these datasets and reads as before.
  const Medium one = build_medium(testing::coarse_grain_tiny(), 901);
  write_medium_file(dir + "/one.h5", MediumFile{one, 901, testing::coarse_grain_tiny().medium_text, "test", {}});
  const Medium one_back = read_medium_file(dir + "/one.h5").medium;
  EXPECT_EQ(one_back.levels, 1);
  EXPECT_TRUE(one_back.inner_sites.empty());
}

// Both models of the nested medium compress: the resolved one with free shells inside free shells.
TEST(NestedMedium, BothModelsCompress) {
  const Medium& m = medium();
  for (const CoarseModel model : {CoarseModel::resolved, CoarseModel::soft}) {
    const CompressionRun run = run_compression(medium_scene(nested(), m, model, laws()), m, model, nested(), {}, {});
    ASSERT_EQ(run.rows.size(), 10u) << name(model);
    EXPECT_GT(run.rows[6].sigma_top, 0.0) << name(model);
    EXPECT_NEAR(run.rows[6].strain, 0.06, 1e-3) << name(model);
  }
}

// sample_contents (packing/nested.hpp) by hand: the first M level-1 packings breadth first from
// the top packings of seeds nested_site_seed(seed, k), each level-1 content's quantities its
// grains' (the last level: no sites), their mean and standard error.
TEST(NestedMedium, TheSampledContentIsTheMeanOfTheFirstPackingsBreadthFirst) {
  const PackingParameters& p = nested().packing;
  constexpr std::size_t M = 5;
  std::vector<double> v, g;
  double smallest = 1.0;
  for (std::size_t k = 0; v.size() < M; ++k) {
    const std::uint64_t top = nested_site_seed(77, k);
    const LevelPacking up = generate_level(p, 1, top);
    for (std::size_t i = 0; i < up.sites.size() && v.size() < M; ++i) {
      const LevelPacking l = generate_level(level_parameters(p, 1), 0, nested_site_seed(top, i));
      EXPECT_TRUE(l.sites.empty());
      double vol = 0.0;
      for (double r : l.grains.radii) vol += ball(r), smallest = std::min(smallest, r);
      v.push_back(vol), g.push_back(static_cast<double>(l.grains.radii.size()));
    }
  }
  const auto mean_se = [](const std::vector<double>& x) {
    double m = 0.0, s2 = 0.0;
    for (double xi : x) m += xi / static_cast<double>(x.size());
    for (double xi : x) s2 += (xi - m) * (xi - m) / static_cast<double>(x.size() - 1);
    return std::pair{m, std::sqrt(s2 / static_cast<double>(x.size()))};
  };
  const ContentMean c = sample_contents(p, 1, 77, M);
  EXPECT_EQ(c.sample, M);
  EXPECT_NEAR(c.volume, mean_se(v).first, 1e-12 * c.volume);
  EXPECT_NEAR(c.volume_error, mean_se(v).second, 1e-9 * c.volume_error);
  EXPECT_GT(c.volume_error, 0.0) << "five packings of the same volume: the sample tests nothing";
  EXPECT_NEAR(c.shells_volume, c.volume, 1e-12 * c.volume) << "a last-level content has one shell, around its own grains";
  EXPECT_NEAR(c.grains, mean_se(g).first, 1e-12 * c.grains);
  EXPECT_NEAR(c.grains_error, mean_se(g).second, 1e-9 * c.grains);
  EXPECT_EQ(c.smallest_radius, smallest);
  EXPECT_THROW(sample_contents(p, 1, 77, 1), InputError);
  EXPECT_THROW(sample_contents(p, 0, 77, M), InputError);
}

// One level deeper the recursion X = x + n X' holds with level 2's mean inside each level-1 packing,
// and the error carries the level below's: se² = s²/M + mean(n)² se'².
TEST(NestedMedium, TheSampledContentTwoLevelsDownHoldsTheMeanOfTheLevelBelow) {
  PackingParameters p = nested().packing;
  p.Rs *= 3.0, p.r_max *= 3.0;  // three levels of the tiny profile's, the last as the tiny medium's
  constexpr std::size_t M = 4;
  const ContentMean c = sample_contents(p, 2, 78, M);
  // Level 1's sample by hand and level 2's breadth first from it.
  std::vector<std::uint64_t> l1;
  std::vector<LevelPacking> level1;
  for (std::size_t k = 0; level1.size() < M; ++k) {
    const std::uint64_t top = nested_site_seed(78, k);
    const LevelPacking up = generate_level(p, 2, top);
    for (std::size_t i = 0; i < up.sites.size() && level1.size() < M; ++i)
      l1.push_back(nested_site_seed(top, i)), level1.push_back(generate_level(level_parameters(p, 1), 1, l1.back()));
  }
  std::vector<double> v2, g2;  // level 2: the last, grains only
  const PackingParameters p2 = level_parameters(level_parameters(p, 1), 1);  // chained, as generate_contents
  for (std::size_t k = 0; k < level1.size() && v2.size() < M; ++k)
    for (std::size_t i = 0; i < level1[k].sites.size() && v2.size() < M; ++i) {
      const LevelPacking l = generate_level(p2, 0, nested_site_seed(l1[k], i));
      double vol = 0.0;
      for (double r : l.grains.radii) vol += ball(r);
      v2.push_back(vol), g2.push_back(static_cast<double>(l.grains.radii.size()));
    }
  ASSERT_EQ(v2.size(), M);
  const auto mean_s2 = [](const std::vector<double>& x) {
    double m = 0.0, s2 = 0.0;
    for (double xi : x) m += xi / M;
    for (double xi : x) s2 += (xi - m) * (xi - m) / (M - 1);
    return std::pair{m, s2};
  };
  const auto [V2, s2] = mean_s2(v2);
  const double G2 = mean_s2(g2).first, W2 = V2;  // a last-level content's shells: its own
  // Level 1: x + n X' for the volume, the shells (x + n (V' + W')) and the grains.
  std::vector<double> v1, w1, g1;
  double n_mean = 0.0;
  for (const LevelPacking& l : level1) {
    double vol = 0.0;
    for (double r : l.grains.radii) vol += ball(r);
    const auto n = static_cast<double>(l.sites.size());
    v1.push_back(vol + n * V2), w1.push_back(vol + n * (V2 + W2)), g1.push_back(static_cast<double>(l.grains.radii.size()) + n * G2);
    n_mean += n / M;
  }
  ASSERT_GT(n_mean, 0.0) << "level 1 holds no site: the test tests nothing";
  const auto [V1, s1] = mean_s2(v1);
  EXPECT_NEAR(c.volume, V1, 1e-12 * V1);
  EXPECT_NEAR(c.volume_error, std::sqrt(s1 / M + n_mean * n_mean * s2 / M), 1e-9 * c.volume_error);
  EXPECT_NEAR(c.shells_volume, mean_s2(w1).first, 1e-12 * c.shells_volume);
  EXPECT_NEAR(c.grains, mean_s2(g1).first, 1e-12 * c.grains);
  // The shells' volume of made contents is content_shells_mass at unit density and fraction: the
  // same recursion on the level-1 sample's own contents, one by one.
  for (std::size_t k = 0; k < M; ++k) {
    SiteContent made;
    made.level = level1[k];
    made.sites = generate_contents(level_parameters(p, 1), 1, l1[k], level1[k].sites.size());
    double w = 0.0;
    for (double r : made.level.grains.radii) w += ball(r);
    for (const SiteContent& sub : made.sites) w += 2.0 * sub.solid_volume();  // each inner site: its volume, in two shells
    EXPECT_NEAR(content_shells_mass(made, 1.0, 1.0), w, 1e-12 * w) << "level-1 packing " << k;
  }
}

// A medium of sampled contents (medium.content_sample): no content made, each site's sites
// weighed by the mean (the soft-particle's mass, the volume counted against the target), kept in
// its file; the resolved model refused; the estimate counts the mean's grains with its error.
TEST(NestedMedium, ASampledMediumWeighsItsSitesSitesByTheMean) {
  CoarseGrainSettings s = nested();
  s.content_sample = 6;
  const Medium m = build_medium(s, 901);
  ASSERT_TRUE(m.contents.empty());
  ASSERT_EQ(m.content_mean.sample, 6u);
  const ContentMean& c = m.content_mean;
  const double rho = s.simulation.material.density, f = s.shell_mass_fraction;
  double V = 0.0, exact_spheres = static_cast<double>(m.grain_r.size()), n_all = 0.0;
  const SceneDef soft = medium_scene(s, m, CoarseModel::soft, laws());
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const auto n = static_cast<double>(m.inner_sites[k].size());
    n_all += n;
    double own = 0.0;
    for (double r : m.packings[k].radii) own += ball(r);
    V += own + n * c.volume;
    exact_spheres += static_cast<double>(m.packings[k].radii.size());
    const double mass = (1.0 + f) * rho * (own + n * c.volume) + f * rho * n * c.shells_volume;
    EXPECT_NEAR(*soft.particles[m.grain_x.size() + k].mass, mass, 1e-12 * mass) << "site " << k;
  }
  ASSERT_GT(n_all, 0.0) << "no site holds a site: the test tests nothing";
  EXPECT_NEAR(m.packings_volume, V, 1e-12 * V);
  EXPECT_THROW(medium_scene(s, m, CoarseModel::resolved, laws()), InputError);
  EXPECT_THROW(sphere_bodies(m, CoarseModel::resolved), InputError);

  // The made medium of the same seed: its sites' sites, site by site over the sites both have,
  // within three standard deviations of n contents (the sample's spread) and of the mean's error.
  const Medium& made = medium();
  double made_v = 0.0, sampled_v = 0.0, n_common = 0.0;
  for (std::size_t k = 0; k < std::min(m.sites.size(), made.sites.size()); ++k) {
    ASSERT_EQ(m.inner_sites[k], made.inner_sites[k]) << "the same seeds, the same sites";
    made_v += site_inside(made, k).volume, sampled_v += site_inside(m, k).volume;
    n_common += static_cast<double>(m.inner_sites[k].size());
  }
  const double sd = c.volume_error * std::sqrt(static_cast<double>(c.sample));
  EXPECT_NEAR(made_v, sampled_v, 3.0 * std::hypot(std::sqrt(n_common) * sd, n_common * c.volume_error));

  // Its file keeps the mean; the settings must sample as it did.
  const std::string dir = ::testing::TempDir() + "/nested-medium";
  std::filesystem::create_directories(dir);
  write_medium_file(dir + "/sampled.h5", MediumFile{m, 901, s.medium_text, "test", {}});
  Medium back = read_medium_file(dir + "/sampled.h5").medium;
  EXPECT_EQ(back.content_mean.sample, 6u);
  EXPECT_EQ(back.content_mean.volume, c.volume);
  EXPECT_EQ(back.content_mean.shells_volume_error, c.shells_volume_error);
  EXPECT_EQ(back.content_mean.grains, c.grains);
  EXPECT_EQ(back.content_mean.smallest_radius, c.smallest_radius);
  EXPECT_THROW(medium_contents(nested(), back), InputError) << "made contents asked of a sampled medium";
  medium_contents(s, back);
  EXPECT_TRUE(back.contents.empty());
  Medium made_back = made;
  made_back.contents.clear();
  EXPECT_THROW(medium_contents(s, made_back), InputError) << "a sample asked of a made medium";

  CoarseResult run;
  run.path = "soft.h5", run.model = "soft", run.steps = 1000, run.dt = 1e-6, run.cpu_seconds = 2.0;
  run.grains = static_cast<std::int64_t>(m.grain_x.size()), run.sites = static_cast<std::int64_t>(m.sites.size());
  CoarseResult a;
  a.path = "a.h5", a.model = "resolved", a.spheres = 100, a.steps = 1000, a.cpu_seconds = 10.0;
  const ResolvedEstimate e = estimate_resolved(s, back, run, {a, a});
  EXPECT_NEAR(e.spheres, exact_spheres + n_all * c.grains, 1e-9 * e.spheres);
  EXPECT_NEAR(e.spheres_error, n_all * c.grains_error, 1e-9 * e.spheres_error);
  EXPECT_LE(e.smallest_radius, c.smallest_radius);
  EXPECT_NEAR(e.cpu_error, e.cpu * e.spheres_error / e.spheres, 1e-9 * e.cpu) << "c measured twice the same: its error is 0";
  EXPECT_EQ(e.content_sample, 6u);
  // Planned deeper, the sampled part and its error grow by the same ratio.
  CoarseGrainSettings deeper = s;
  deeper.plan_levels_added = 1;
  const DeeperPlan d = estimate_resolved(deeper, back, run, {a, a}).deeper;
  EXPECT_NEAR(d.spheres, exact_spheres + d.depth_ratio * n_all * c.grains, 1e-9 * d.spheres);
  EXPECT_NEAR(d.spheres_error, d.depth_ratio * n_all * c.grains_error, 1e-9 * d.spheres_error);
}

}  // namespace nested_medium_test
}  // namespace softpack
