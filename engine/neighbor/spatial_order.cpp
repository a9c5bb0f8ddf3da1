#include "neighbor/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace softpack {
namespace {

constexpr int kBits = 10;  // cells per side: 2^10

// The bits of v spread to every third position: b9 .. b0 -> b9 0 0 b8 0 0 ... b0.
std::uint32_t spread(std::uint32_t v) {
  std::uint32_t out = 0;
  for (int b = 0; b < kBits; ++b) out |= ((v >> b) & 1u) << (3 * b);
  return out;
}

}  // namespace

std::vector<std::int32_t> spatial_order(const std::vector<Vec3>& x) {
  std::vector<std::int32_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  if (x.empty()) return order;
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& p : x) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double cells = double(1u << kBits);
  std::vector<std::uint32_t> key(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      const double extent = hi[a] - lo[a];
      const double f = extent > 0.0 ? (x[k][a] - lo[a]) / extent : 0.0;
      const auto cell = static_cast<std::uint32_t>(std::clamp(std::floor(f * cells), 0.0, cells - 1.0));
      code |= spread(cell) << a;
    }
    key[k] = code;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)]; });
  return order;
}

}  // namespace softpack
