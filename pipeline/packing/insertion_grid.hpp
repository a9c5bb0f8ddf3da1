// Spheres stored one at a time, for the packing generator: "does this sphere overlap any
// stored one?" and "how far is the nearest stored sphere?". Multi-level hashed grid like
// neighbor/hierarchical_grid.hpp (levels of cell size c_l = c_0 q^l, a sphere on the lowest
// level whose cell holds its diameter), but incremental: spheres are inserted, and may grow.
// A query scans, on every populated level, the cells its search box touches, or the level's
// spheres one by one when they are fewer than those cells (a wide search on a fine, sparse
// level: a tiny grain in a large void at high polydispersity). A sphere that grows beyond its
// cell moves up to the level that fits it, so that a level's largest radius stays of the order
// of its cell and queries on fine levels stay narrow.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "scene/limits.hpp"

namespace softpack {

class InsertionGrid {
 public:
  /// Levels for radii in [r_min, r_max] (larger radii go to the top level).
  InsertionGrid(double r_min, double r_max, double level_ratio);

  /// Stores a sphere; its id is the insertion order.
  int insert(const Vec3& x, double r);
  /// True if (x, r) overlaps a stored sphere: |x - xj| < r + rj.
  bool overlaps(const Vec3& x, double r) const;
  /// Smallest surface gap |x - xj| - r - rj to a stored sphere other than `self`, among those
  /// with a gap below `search`; +infinity when there is none.
  double nearest_gap(const Vec3& x, double r, int self, double search) const;
  /// The stored sphere other than `self` whose centre is nearest to x, among those whose centre
  /// lies within `search` of x: {distance, id}; {+infinity, -1} when there is none.
  std::pair<double, int> nearest_centre(const Vec3& x, int self, double search) const;
  /// Grows (or shrinks) a stored sphere in place.
  void set_radius(int id, double r);

  std::size_t size() const { return x_.size(); }
  const Vec3& centre(int id) const { return x_[id]; }
  double radius(int id) const { return r_[id]; }
  /// Level a sphere is stored on (0 is the finest).
  int level(int id) const { return level_of_[id]; }

 private:
  using Key = std::uint64_t;
  struct Level {
    double cell = 0.0, inv_cell = 0.0;
    double r_max = 0.0;  ///< largest radius stored on the level
    std::vector<int> head;  ///< hash buckets, -1 when empty
    int shift = 64;
    std::size_t population = 0;
    std::vector<int> members;  ///< the spheres stored on the level, in no particular order
  };
  static constexpr std::int64_t kOffset = std::int64_t{1} << 20;  // cell coordinates may be negative
  static_assert(static_cast<double>(kOffset) == limits::kInsertionCells, "validate(PackingParameters) keeps the shell within");

  static Key pack(std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    return (static_cast<Key>(cx + kOffset) << 42) | (static_cast<Key>(cy + kOffset) << 21) |
           static_cast<Key>(cz + kOffset);
  }
  static std::size_t bucket(Key k, const Level& L) {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> L.shift);
  }
  std::int64_t coordinate(double v, const Level& L) const {
    return static_cast<std::int64_t>(std::floor(v * L.inv_cell));
  }
  void rehash(Level& L);
  /// Level whose cell holds a sphere of radius r (the top level for larger ones).
  std::size_t level_for(double r) const;
  /// Puts sphere `id` (position and radius set) on level l; unlinks it from its old level.
  void link(int id, std::size_t l);
  void unlink(int id);
  /// Calls visit(id) for every stored sphere whose centre lies within `range` (per axis) of x
  /// on level L; stops when visit returns true.
  template <class Visit>
  bool scan(const Level& L, const Vec3& x, double range, Visit&& visit) const;

  std::vector<Level> levels_;
  std::vector<Vec3> x_;
  std::vector<double> r_;
  std::vector<int> level_of_;
  std::vector<Key> cell_;
  std::vector<int> next_;
  std::vector<std::size_t> member_index_;  ///< position of each sphere in its level's members
};

template <class Visit>
bool InsertionGrid::scan(const Level& L, const Vec3& x, double range, Visit&& visit) const {
  const std::int64_t x0 = coordinate(x.x() - range, L), x1 = coordinate(x.x() + range, L);
  const std::int64_t y0 = coordinate(x.y() - range, L), y1 = coordinate(x.y() + range, L);
  const std::int64_t z0 = coordinate(x.z() - range, L), z1 = coordinate(x.z() + range, L);
  const double cells = static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) * static_cast<double>(z1 - z0 + 1);
  if (cells > static_cast<double>(L.members.size())) {
    // Fewer spheres than cells: every sphere of the level (a superset of the box's; the
    // callers test the distance, and their answers do not depend on the order of visits).
    for (const int j : L.members)
      if (visit(j)) return true;
    return false;
  }
  for (std::int64_t cz = z0; cz <= z1; ++cz)
    for (std::int64_t cy = y0; cy <= y1; ++cy)
      for (std::int64_t cx = x0; cx <= x1; ++cx) {
        const Key c = pack(cx, cy, cz);
        for (int j = L.head[bucket(c, L)]; j != -1; j = next_[j])
          if (cell_[j] == c && visit(j)) return true;
      }
  return false;
}

}  // namespace softpack
