// The hierarchical grid finds exactly the brute-force contact set, whatever the polydispersity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "neighbor/hierarchical_grid.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

using PairSet = std::set<std::pair<int, int>>;

PairSet brute_force(const std::vector<Vec3>& x, const std::vector<double>& r, double skin) {
  PairSet out;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const double s = r[i] + r[j] + skin;
      if ((x[i] - x[j]).squaredNorm() < s * s) out.insert({static_cast<int>(i), static_cast<int>(j)});
    }
  return out;
}

struct Case {
  double polydispersity;
  double skin_fraction;  // of r_min
  double level_ratio;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << "Pi=" << c.polydispersity << " skin=" << c.skin_fraction << " ratio=" << c.level_ratio;
}

class GridMatchesBruteForce : public ::testing::TestWithParam<Case> {};

TEST_P(GridMatchesBruteForce, OnRandomConfigurations) {
  const Case c = GetParam();
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    testing::Random rng(seed);
    const double r_max = 0.05, r_min = r_max / c.polydispersity;
    // 2000 spheres with a power-law size distribution (b = 2.5 keeps some large ones) in a box
    // whose size gives a solid fraction of 0.5: many contacts of every size class.
    auto cloud = testing::random_cloud(rng, 2000, 0.5, r_min, r_max, 2.5);
    double volume = 0.0;
    for (const auto& p : cloud) volume += 4.0 / 3.0 * std::numbers::pi * std::pow(p.r, 3);
    const double side = std::cbrt(volume / 0.5);
    for (auto& p : cloud) p.x *= side;
    // Add exact touching pairs and coincident centres, the edge cases of the distance test.
    cloud[1].x = cloud[0].x + Vec3(cloud[0].r + cloud[1].r, 0, 0);
    cloud[3].x = cloud[2].x;
    std::vector<Vec3> x;
    std::vector<double> r;
    for (const auto& p : cloud) {
      x.push_back(p.x);
      r.push_back(p.r);
    }
    const double skin = c.skin_fraction * r_min;
    const PairSet expected = brute_force(x, r, skin);
    EXPECT_GT(expected.size(), 100u);
    // Both indexings: automatic (this compact cloud: dense levels, cross-level pairs searched
    // from the side the cost estimate picks) and every level hashed, searched from the fine side.
    for (const auto indexing : {HierarchicalGrid::Indexing::automatic, HierarchicalGrid::Indexing::hashed}) {
      HierarchicalGrid grid;
      grid.build(x, r, skin, c.level_ratio, indexing);
      PairSet found;
      std::size_t reports = 0;
      grid.for_each_pair([&](int i, int j) {
        found.insert({std::min(i, j), std::max(i, j)});
        ++reports;
      });
      const bool hashed = indexing == HierarchicalGrid::Indexing::hashed;
      EXPECT_EQ(reports, found.size()) << "a pair was reported twice" << (hashed ? " (hashed)" : "");
      EXPECT_EQ(found, expected) << "polydispersity " << c.polydispersity << " seed " << seed << (hashed ? " (hashed)" : "");
      if (hashed) {
        for (std::size_t l = 0; l < grid.level_count(); ++l) EXPECT_FALSE(grid.level_is_dense(l)) << "level " << l;
      }
    }
  }
}

// The two search directions and the dense indexing are really used where they pay: a power law
// with few big spheres searches their pairs with the small ones from the big side.
TEST(HierarchicalGrid, SparseCoarseLevelsAreSearchedFromTheCoarseSide) {
  testing::Random rng(7);
  const double r_max = 0.05, r_min = r_max / 100;
  auto cloud = testing::random_cloud(rng, 3000, 0.5, r_min, r_max, 3.5);
  double volume = 0.0;
  for (const auto& p : cloud) volume += 4.0 / 3.0 * std::numbers::pi * std::pow(p.r, 3);
  const double side = std::cbrt(volume / 0.5);
  std::vector<Vec3> x;
  std::vector<double> r;
  for (const auto& p : cloud) {
    x.push_back(p.x * side);
    r.push_back(p.r);
  }
  HierarchicalGrid grid;
  grid.build(x, r, 0.2 * r_min, 4.0);
  ASSERT_GE(grid.level_count(), 3u);
  std::size_t dense = 0, from_coarse = 0;
  for (std::size_t f = 0; f < grid.level_count(); ++f) {
    dense += grid.level_is_dense(f) ? 1 : 0;
    for (std::size_t c = f + 1; c < grid.level_count(); ++c) from_coarse += grid.searched_from_coarse(f, c) ? 1 : 0;
  }
  EXPECT_GE(dense, 2u);
  EXPECT_GE(from_coarse, 1u);
  PairSet found;
  grid.for_each_pair([&](int i, int j) { found.insert({std::min(i, j), std::max(i, j)}); });
  EXPECT_EQ(found, brute_force(x, r, 0.2 * r_min));
  // Searched in parts (the threads' cut of a rebuild): together every pair, each once, with the
  // coarse-side search on (from_coarse above).
  for (const std::size_t parts : {2u, 3u, 7u}) {
    PairSet of_parts;
    std::size_t reported = 0;
    for (std::size_t t = 0; t < parts; ++t)
      grid.for_each_pair([&](int i, int j) { of_parts.insert({std::min(i, j), std::max(i, j)}), ++reported; }, t, parts);
    EXPECT_EQ(of_parts, found) << parts << " parts";
    EXPECT_EQ(reported, found.size()) << parts << " parts";
  }
}

INSTANTIATE_TEST_SUITE_P(Polydispersity, GridMatchesBruteForce,
                         ::testing::Values(Case{1, 0.0, 2.0}, Case{10, 0.0, 2.0}, Case{100, 0.0, 2.0},
                                           Case{1000, 0.0, 2.0}, Case{1, 0.3, 2.0}, Case{10, 0.3, 3.0},
                                           Case{100, 0.3, 1.5}, Case{1000, 0.3, 4.0}),
                         [](const auto& info) {
                           return "Pi" + std::to_string(static_cast<int>(info.param.polydispersity)) + "_case" +
                                  std::to_string(info.index);
                         });

TEST(HierarchicalGrid, LevelsCoverTheSizeRange) {
  std::vector<Vec3> x{Vec3::Zero(), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  std::vector<double> r{0.001, 0.01, 0.1};
  HierarchicalGrid grid;
  grid.build(x, r, 0.0, 2.0);
  // c_0 = 2 r_min; cells double until they hold the largest sphere: 0.002 * 2^l >= 0.2.
  EXPECT_EQ(grid.level_count(), 8u);
  EXPECT_DOUBLE_EQ(grid.level_cell_size(0), 0.002);
  EXPECT_GE(grid.level_cell_size(grid.level_count() - 1), 0.2);
  std::size_t total = 0;
  for (std::size_t l = 0; l < grid.level_count(); ++l) total += grid.level_population(l);
  EXPECT_EQ(total, 3u);
}

}  // namespace
}  // namespace softpack
