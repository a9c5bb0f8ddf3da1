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
#include "sim/simulation.hpp"
#include "support/coarse_tiny.hpp"

namespace softpack {
namespace nested_medium_test {

// The tiny medium's settings (quick profile, Π = 3) with its sites at two levels.
const CoarseGrainSettings& nested() {
  static const CoarseGrainSettings s = [] {
    CoarseGrainSettings n = testing::coarse_grain_tiny();
    n.levels = 2;
    return n;
  }();
  return s;
}

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

// The resolved model's cost estimate (coarse/resolved_estimate.hpp): N spheres, the engine's own
// step for the resolved scene, the soft run's simulated time over it, the measured runs' mean CPU
// time per sphere-step; a run of another medium or of the wrong model refused.
TEST(NestedMedium, TheResolvedEstimateIsSpheresTimesStepsTimesTheMeasuredCost) {
  const Medium& m = medium();
  const SceneDef resolved = medium_scene(nested(), m, CoarseModel::resolved, laws());
  CoarseResult soft;
  soft.path = "soft.h5", soft.model = "soft", soft.steps = 1000, soft.dt = 1e-6, soft.cpu_seconds = 2.0;
  soft.grains = static_cast<std::int64_t>(m.grain_x.size()), soft.sites = static_cast<std::int64_t>(m.sites.size());
  CoarseResult a, b;
  a.path = "a.h5", b.path = "b.h5", a.model = b.model = "resolved";
  a.spheres = b.spheres = 100, a.steps = b.steps = 1000, a.cpu_seconds = 10.0, b.cpu_seconds = 30.0;  // 1e-4 and 3e-4 s
  const ResolvedEstimate e = estimate_resolved(nested(), m, soft, {a, b});
  EXPECT_EQ(e.spheres, resolved.particles.size());
  EXPECT_NEAR(e.dt, Simulation(resolved).dt(), 1e-12 * e.dt) << "the engine's step for the whole resolved scene";
  EXPECT_NEAR(e.steps, 1000 * 1e-6 / e.dt, 1e-9 * e.steps);
  EXPECT_NEAR(e.cpu_per_sphere_step, 2e-4, 1e-15);
  EXPECT_NEAR(e.cpu_per_sphere_step_error, 1e-4, 1e-15);
  EXPECT_NEAR(e.cpu, static_cast<double>(e.spheres) * e.steps * 2e-4, 1e-9 * e.cpu);
  EXPECT_NEAR(e.speed_up(), e.cpu / 2.0, 1e-9 * e.speed_up());
  CoarseResult other = soft;
  other.sites += 1;
  EXPECT_THROW(estimate_resolved(nested(), m, other, {a}), InputError);
  EXPECT_THROW(estimate_resolved(nested(), m, soft, {soft}), InputError);
  EXPECT_THROW(estimate_resolved(nested(), m, soft, {}), InputError);
}

}  // namespace nested_medium_test
}  // namespace softpack
