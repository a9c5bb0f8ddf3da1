// The nested generator (packing/nested.hpp, docs/nested.md): a level's list carries the decade
// below in sites at the power law's volume, sites and grains placed together without overlap,
// the grains grown and the sites kept at Rs / Π, and without levels below the plain packing's
// bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/error.hpp"
#include "core/random.hpp"
#include "formats/packing_file.hpp"
#include "measure/contact_scenes.hpp"
#include "measure/settings.hpp"
#include "packing/generator.hpp"
#include "packing/nested.hpp"
#include "packing/statistics.hpp"
#include "support/level_packing.hpp"
#include "support/temp_dir.hpp"

namespace softpack {
namespace {

using testing::level_packing;  // a level with Π = √10

TEST(NestedPacking, WithoutLevelsBelowItIsThePlainPacking) {
  PackingParameters p = level_packing();
  p.polydispersity = 5.0;
  const Packing a = generate_packing(p, 21);
  const LevelPacking b = generate_level(p, 0, 21);
  ASSERT_EQ(a.radii.size(), b.grains.radii.size());
  EXPECT_EQ(std::memcmp(a.centres.data(), b.grains.centres.data(), a.centres.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.radii.data(), b.grains.radii.data(), a.radii.size() * sizeof(double)), 0);
  EXPECT_EQ(a.sampled, b.grains.sampled);
  EXPECT_EQ(a.discarded, b.grains.discarded);
  EXPECT_EQ(a.grown, b.grains.grown);
  EXPECT_TRUE(b.sites.empty());
  EXPECT_EQ(b.sites_drawn, 0u);
}

// The count of sites is the list volume of the decade below (Π^-(4-b) of the grains' list
// volume) over what one site's own list holds (β V_site at Rs / Π): analytic, from the drawn list.
TEST(NestedPacking, SitesCarryTheDecadeBelowAtThePowerLaw) {
  const PackingParameters p = level_packing();
  Random rng(31);
  double volume = 0.0;
  for (double r : sample_list(p, rng)) volume += r * r * r;
  const double below = volume * std::pow(p.polydispersity, -(4.0 - p.exponent));
  const double site = p.beta * std::pow(p.Rs / p.polydispersity, 3.0);
  EXPECT_EQ(site_count(p, volume), static_cast<std::size_t>(std::llround(below / site)));
  const LevelPacking l = generate_level(p, 1, 31);
  EXPECT_EQ(l.sites_drawn, site_count(p, volume));
  EXPECT_EQ(l.sites_drawn, l.sites.size() + l.sites_discarded);
  EXPECT_GE(l.sites.size(), 1u);
  EXPECT_DOUBLE_EQ(l.site_radius, p.Rs / p.polydispersity);
  EXPECT_EQ(l.grains.sampled, l.grains.radii.size() + l.grains.discarded);
}

TEST(NestedPacking, SitesAndGrainsDoNotOverlapSitesKeepTheirRadiusGrainsGrow) {
  const PackingParameters p = level_packing();
  const LevelPacking l = generate_level(p, 1, 41);
  std::vector<Vec3> x = l.grains.centres;
  std::vector<double> r = l.grains.radii;
  for (const Vec3& s : l.sites) x.push_back(s), r.push_back(l.site_radius);
  constexpr double kRelative = 1e-12;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_LE(x[i].norm() + r[i], p.Rs * (1 + kRelative)) << "body " << i << " crosses the shell";
    double nearest = p.Rs - x[i].norm() - r[i];
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (j == i) continue;
      const double gap = (x[i] - x[j]).norm() - r[i] - r[j];
      ASSERT_GE(gap, -kRelative * (r[i] + r[j])) << "bodies " << i << " and " << j << " overlap";
      nearest = std::min(nearest, gap);
    }
    if (i < l.grains.radii.size() && l.grains.radii[i] > l.grains.radii_inserted[i]) {
      EXPECT_LE(std::abs(nearest), 1e-12 * p.Rs) << "grown grain " << i << " is " << nearest << " m from its neighbour";
      ++touching;
    }
  }
  EXPECT_EQ(touching, l.grains.grown);
  EXPECT_GT(l.grains.grown, 0u);
}

TEST(NestedPacking, LevelsDivideEveryLengthByPi) {
  const PackingParameters p = level_packing();
  const PackingParameters q = level_parameters(p, 2);
  EXPECT_NEAR(q.Rs, p.Rs / 10.0, 1e-15);
  EXPECT_NEAR(q.r_max, p.r_max / 10.0, 1e-15);
  // the decade below begins where this one ends
  EXPECT_NEAR(level_parameters(p, 1).r_max, p.r_max / p.polydispersity, 1e-15);
  EXPECT_EQ(q.polydispersity, p.polydispersity);
  EXPECT_EQ(q.beta, p.beta);
}

TEST(NestedPacking, SameSeedSameBitsAndSiteSeeds) {
  const PackingParameters p = level_packing();
  const LevelPacking a = generate_level(p, 1, 51), b = generate_level(p, 1, 51);
  ASSERT_EQ(a.sites.size(), b.sites.size());
  EXPECT_EQ(std::memcmp(a.sites.data(), b.sites.data(), a.sites.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(nested_site_seed(601, 7), 601007u);
  EXPECT_THROW(nested_site_seed(601, kMaxSites), InputError);
  EXPECT_THROW(nested_site_seed(kMaxSeed / 100, 0), InputError);
}

TEST(NestedPacking, RefusesLevelsItCannotHold) {
  PackingParameters p = level_packing();
  EXPECT_THROW(validate_levels(p, 0), InputError);
  EXPECT_THROW(validate_levels(p, 7), InputError);
  EXPECT_NO_THROW(validate_levels(p, 3));
  p.polydispersity = 20.0;  // 20^2.5 = 1789 sites per level
  try {
    validate_levels(p, 2);
    FAIL() << "20^2.5 sites accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("packing.levels"), std::string::npos) << e.what();
  }
  p = level_packing();
  p.Rs = 1e-8, p.r_max = 0.3e-8;  // the last level's grains below the smallest length
  EXPECT_THROW(validate_levels(p, 3), InputError);
}

// The packing file keeps the level's sites; a packing without levels keeps its identity; the
// measurement scenes refuse a packing whose sites they would leave out (a profile without
// `content`).
TEST(NestedPacking, TheFileKeepsTheSitesAndTheScenesRefuseThem) {
  testing::TempDir dir("nested-file");
  const PackingParameters p = level_packing();
  const LevelPacking l = generate_level(p, 1, 61);
  ASSERT_FALSE(l.sites.empty());
  const PackingStatistics stats = packing_statistics(l.grains.centres, l.grains.radii, p.Rs, p.r_max, 10);
  PackingProvenance prov;
  prov.program = "softpack-pack";
  prov.seed = 61;
  const PackingSites sites{2, l.site_radius, l.sites, l.sites_drawn, l.sites_discarded};
  write_packing_file(dir / "nested.h5", p, l.grains, stats, prov, sites);
  write_packing_file(dir / "plain.h5", p, l.grains, stats, prov);
  const PackingFile nested = read_packing_file(dir / "nested.h5"), plain = read_packing_file(dir / "plain.h5");
  EXPECT_EQ(nested.sites.levels, 2);
  EXPECT_EQ(nested.sites.radius, l.site_radius);
  EXPECT_EQ(nested.sites.centres, l.sites);
  EXPECT_EQ(nested.sites.drawn, l.sites_drawn);
  EXPECT_EQ(plain.sites.levels, 1);
  EXPECT_TRUE(plain.sites.centres.empty());
  EXPECT_NE(packing_sha256(nested), packing_sha256(plain));
  PackingFile moved = plain;
  moved.sites = nested.sites;
  moved.sites.levels = 1;  // levels 1: the sites are not part of the identity
  EXPECT_EQ(packing_sha256(moved), packing_sha256(plain));
  SimulationSettings settings;
  EXPECT_NO_THROW(soft_solid_setup(plain, settings));
  try {
    soft_solid_setup(nested, settings);
    FAIL() << "a packing with sites was measured without them";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("packing.levels"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace softpack
