// neighbor/spatial_order.hpp: the Z-order of points, a permutation that keeps ties in order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "neighbor/spatial_order.hpp"

namespace softpack {
namespace {

// The corners of a cube come in Z-order: x is the fastest bit, then y, then z.
TEST(SpatialOrder, CubeCornersFollowTheZCurve) {
  std::vector<Vec3> x;
  for (int k = 7; k >= 0; --k) x.push_back(Vec3((k & 1) ? 1.0 : 0.0, (k & 2) ? 1.0 : 0.0, (k & 4) ? 1.0 : 0.0));
  const std::vector<std::int32_t> order = spatial_order(x);
  ASSERT_EQ(order.size(), 8u);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(order[static_cast<std::size_t>(k)], 7 - k) << "corner " << k;
}

// A permutation; points of one cell keep their order; no extent along an axis is fine.
TEST(SpatialOrder, APermutationThatKeepsTies) {
  std::vector<Vec3> x{{0.5, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const std::vector<std::int32_t> order = spatial_order(x);
  EXPECT_EQ(order, (std::vector<std::int32_t>{1, 4, 0, 2, 3}));
  EXPECT_TRUE(spatial_order({}).empty());
  std::vector<Vec3> many;
  for (int k = 0; k < 1000; ++k) many.push_back(Vec3(std::sin(k * 1.3), std::cos(k * 0.7), std::sin(k * 0.11)));
  std::vector<std::int32_t> sorted = spatial_order(many);
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int32_t> all(1000);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(sorted, all);
}

}  // namespace
}  // namespace softpack
