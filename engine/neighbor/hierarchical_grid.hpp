// Multi-level (hierarchical) hashed grid for contact detection of arbitrarily polydisperse
// spheres, after Ogarko & Luding, Comput. Phys. Commun. 183, 931 (2012).
//
// Level l has cubic cells of size c_l = c_0 q^l, with c_0 = 2 r_min + skin and the level ratio
// q > 1. A sphere lives on the lowest level whose cell is at least its "search diameter"
// 2 r + skin, so two spheres of the same level can only be candidates if their cells are
// neighbours. Pairs of different levels are searched only from the smaller sphere into the
// coarser levels, over the few coarse cells that its search box touches (at most 3 per axis),
// so the cost per sphere does not grow with the size ratio, unlike one flat grid sized by the
// largest sphere. Cells are hashed into a table twice the level's population, so memory is
// O(N) whatever the extent of the domain; the spheres of each bucket are stored contiguously
// with their centre and radius (a counting sort per build), so scanning a cell reads one or
// two cache lines instead of chasing a linked list through the particle arrays.
//
// The grid reports every pair whose gap is below `skin`: |xi - xj| < ri + rj + skin.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/types.hpp"

namespace softpack {

class HierarchicalGrid {
 public:
  /// (Re)builds the grid for spheres (x, r); `skin` [m] >= 0, `level_ratio` > 1.
  void build(std::span<const Vec3> x, std::span<const double> r, double skin, double level_ratio);

  /// Calls f(i, j) once for every unordered pair with |xi - xj| < ri + rj + skin.
  template <class F>
  void for_each_pair(F&& f) const;

  std::size_t level_count() const { return levels_.size(); }
  /// Number of spheres stored on level l.
  std::size_t level_population(std::size_t l) const { return levels_[l].population; }
  double level_cell_size(std::size_t l) const { return levels_[l].cell; }

 private:
  // A cell is identified by its integer coordinates on its level, packed 21 bits each into
  // one 64-bit key (coordinates count from the domain's lower corner, so they are >= 0).
  using Cell = std::array<std::int64_t, 3>;
  using Key = std::uint64_t;
  static constexpr int kBits = 21;
  static constexpr std::int64_t kMaxCoordinate = (std::int64_t{1} << kBits) - 1;

  /// A sphere as stored in its level's bucket array.
  struct Entry {
    Vec3 x;
    double r;
    Key cell;
    int id;
  };

  struct Level {
    double cell = 0.0, inv_cell = 0.0;
    double r_max = 0.0;  ///< largest radius stored on this level
    int shift = 64;      ///< 64 - log2(bucket count)
    std::vector<std::uint32_t> start;  ///< entries of bucket b: [start[b], start[b + 1])
    std::vector<Entry> entries;        ///< the level's spheres, grouped by bucket
    std::size_t population = 0;
  };

  static Key pack(std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    return (static_cast<Key>(cx) << (2 * kBits)) | (static_cast<Key>(cy) << kBits) | static_cast<Key>(cz);
  }
  /// Fibonacci hashing: the high bits of k * 2^64/phi depend on every bit of the key.
  static std::size_t bucket(Key k, const Level& L) {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> L.shift);
  }
  std::int64_t coordinate(double x, double origin, const Level& L) const {
    const auto c = static_cast<std::int64_t>(std::floor((x - origin) * L.inv_cell));
    return std::clamp<std::int64_t>(c, 0, kMaxCoordinate);
  }
  Cell cell_of(const Vec3& x, const Level& L) const {
    return {coordinate(x.x(), origin_.x(), L), coordinate(x.y(), origin_.y(), L), coordinate(x.z(), origin_.z(), L)};
  }

  std::span<const Vec3> x_;
  std::span<const double> r_;
  double skin_ = 0.0;
  Vec3 origin_ = Vec3::Zero();
  std::vector<Level> levels_;
  std::vector<int> level_of_;  ///< level of each sphere
  std::vector<Key> cell_;      ///< cell of each sphere on its own level
};

template <class F>
void HierarchicalGrid::for_each_pair(F&& f) const {
  // Half stencil: the own cell (pairs j > i) and the 13 neighbours that follow it in
  // lexicographic order, so each pair of neighbouring cells is visited once.
  static constexpr std::array<std::array<int, 3>, 13> kHalfStencil = {{{1, 0, 0},
                                                                       {-1, 1, 0},
                                                                       {0, 1, 0},
                                                                       {1, 1, 0},
                                                                       {-1, -1, 1},
                                                                       {0, -1, 1},
                                                                       {1, -1, 1},
                                                                       {-1, 0, 1},
                                                                       {0, 0, 1},
                                                                       {1, 0, 1},
                                                                       {-1, 1, 1},
                                                                       {0, 1, 1},
                                                                       {1, 1, 1}}};
  const int n = static_cast<int>(x_.size());
  // Calls `visit(entry)` for every sphere stored in cell c of level L.
  const auto scan = [](const Level& L, Key c, auto&& visit) {
    const std::size_t b = bucket(c, L);
    for (std::uint32_t k = L.start[b], end = L.start[b + 1]; k < end; ++k)
      if (L.entries[k].cell == c) visit(L.entries[k]);
  };
  for (int i = 0; i < n; ++i) {
    const Vec3 xi = x_[i];
    const double ri_skin = r_[i] + skin_;
    const auto test = [&](const Entry& e) {
      const double s = ri_skin + e.r;
      if ((xi - e.x).squaredNorm() < s * s) f(i, e.id);
    };
    const int li = level_of_[i];
    const Level& L = levels_[li];
    const Cell ci = cell_of(xi, L);
    const Key own = cell_[i];
    // Same level, own cell.
    scan(L, own, [&](const Entry& e) {
      if (e.id > i) test(e);
    });
    // Same level, forward neighbours (coordinates are >= 0; a stencil cell at -1 is empty).
    for (const auto& o : kHalfStencil) {
      const std::int64_t cx = ci[0] + o[0], cy = ci[1] + o[1], cz = ci[2] + o[2];
      if (cx < 0 || cy < 0 || cz < 0) continue;
      scan(L, pack(cx, cy, cz), test);
    }
    // Coarser levels: the cells touched by this sphere's search box.
    for (std::size_t lc = static_cast<std::size_t>(li) + 1; lc < levels_.size(); ++lc) {
      const Level& C = levels_[lc];
      if (C.population == 0) continue;
      const double range = ri_skin + C.r_max;
      const Cell lo = cell_of(xi - Vec3::Constant(range), C);
      const Cell hi = cell_of(xi + Vec3::Constant(range), C);
      for (std::int64_t cz = lo[2]; cz <= hi[2]; ++cz)
        for (std::int64_t cy = lo[1]; cy <= hi[1]; ++cy)
          for (std::int64_t cx = lo[0]; cx <= hi[0]; ++cx) scan(C, pack(cx, cy, cz), test);
    }
  }
}

}  // namespace softpack
