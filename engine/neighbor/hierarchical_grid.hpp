// Multi-level (hierarchical) hashed grid for contact detection of arbitrarily polydisperse
// spheres, after Ogarko & Luding, Comput. Phys. Commun. 183, 931 (2012).
//
// Level l has cubic cells of size c_l = c_0 q^l, with c_0 = 2 r_min + skin and the level ratio
// q > 1. A sphere lives on the lowest level whose cell is at least its "search diameter"
// 2 r + skin, so two spheres of the same level can only be candidates if their cells are
// neighbours. Pairs of different levels are searched only from the smaller sphere into the
// coarser levels, over the few coarse cells that its search box touches (at most 3 per axis),
// so the cost per sphere does not grow with the size ratio, unlike one flat grid sized by the
// largest sphere. Cells are hashed (open chaining into a table twice the level's population),
// so memory is O(N) whatever the extent of the domain.
//
// The grid reports every pair whose gap is below `skin`: |xi - xj| < ri + rj + skin.
#pragma once
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
  using Cell = std::array<std::int64_t, 3>;
  struct Level {
    double cell = 0.0, inv_cell = 0.0;
    double r_max = 0.0;  ///< largest radius stored on this level
    std::uint64_t mask = 0;
    std::vector<int> head;  ///< first sphere of each hash bucket, -1 if empty
    std::size_t population = 0;
  };

  static std::uint64_t hash(const Cell& c) {
    std::uint64_t h = static_cast<std::uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull ^
                      static_cast<std::uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full ^
                      static_cast<std::uint64_t>(c[2]) * 0x165667B19E3779F9ull;
    return h ^ (h >> 29);
  }
  Cell cell_of(const Vec3& x, const Level& L) const {
    return {static_cast<std::int64_t>(std::floor((x.x() - origin_.x()) * L.inv_cell)),
            static_cast<std::int64_t>(std::floor((x.y() - origin_.y()) * L.inv_cell)),
            static_cast<std::int64_t>(std::floor((x.z() - origin_.z()) * L.inv_cell))};
  }

  std::span<const Vec3> x_;
  std::span<const double> r_;
  double skin_ = 0.0;
  Vec3 origin_ = Vec3::Zero();
  std::vector<Level> levels_;
  std::vector<int> level_of_;  ///< level of each sphere
  std::vector<Cell> cell_;     ///< cell of each sphere on its own level
  std::vector<int> next_;      ///< next sphere in the same hash bucket, -1 at the end
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
  const auto test = [&](int i, int j) {
    const double s = r_[i] + r_[j] + skin_;
    if ((x_[i] - x_[j]).squaredNorm() < s * s) f(i, j);
  };
  for (int i = 0; i < n; ++i) {
    const int li = level_of_[i];
    const Level& L = levels_[li];
    const Cell& ci = cell_[i];
    // Same level, own cell.
    for (int j = L.head[hash(ci) & L.mask]; j != -1; j = next_[j])
      if (j > i && cell_[j] == ci) test(i, j);
    // Same level, forward neighbours.
    for (const auto& o : kHalfStencil) {
      const Cell c{ci[0] + o[0], ci[1] + o[1], ci[2] + o[2]};
      for (int j = L.head[hash(c) & L.mask]; j != -1; j = next_[j])
        if (cell_[j] == c) test(i, j);
    }
    // Coarser levels: the cells touched by this sphere's search box.
    for (std::size_t lc = static_cast<std::size_t>(li) + 1; lc < levels_.size(); ++lc) {
      const Level& C = levels_[lc];
      if (C.population == 0) continue;
      const double range = r_[i] + skin_ + C.r_max;
      const Cell lo = cell_of(x_[i] - Vec3::Constant(range), C);
      const Cell hi = cell_of(x_[i] + Vec3::Constant(range), C);
      Cell c;
      for (c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
        for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
          for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
            for (int j = C.head[hash(c) & C.mask]; j != -1; j = next_[j])
              if (cell_[j] == c) test(i, j);
    }
  }
}

}  // namespace softpack
