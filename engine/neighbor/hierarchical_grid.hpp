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
// A level whose box of cells is small (at most kDenseCellsPerSphere cells per sphere on it, as
// in any compact packing) is indexed directly instead: cell (cx, cy, cz) is slot
// cx + nx (cy + ny cz). No hashing and no key comparisons, and a row of cells along x is one
// contiguous run of entries, so a 3 x 3 x 3 search box is 9 runs instead of 27 lookups. Both
// indexings report the same pairs; a sparse domain (a sphere flung far away) keeps the hash.
//
// Pairs across a finer level L and a coarser level C are searched from the side a cost
// estimate favours (build() decides per pair of levels): from each L sphere through the few
// big C cells around it, as above, or, when L is dense, from each C sphere through the rows of
// small L cells within reach. The second is cheaper when C is sparse, as the big spheres of a
// power law are: it tests the small spheres near each big one instead of every small sphere
// against the big cells around it, which hold far more volume than the search needs.
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
#include "scene/limits.hpp"

namespace softpack {

class HierarchicalGrid {
 public:
  enum class Indexing { automatic, hashed };  ///< hashed: every level hashed (for tests)
  static constexpr double kDenseCellsPerSphere = 8.0;

  /// (Re)builds the grid for spheres (x, r); `skin` [m] >= 0, `level_ratio` > 1.
  void build(std::span<const Vec3> x, std::span<const double> r, double skin, double level_ratio,
             Indexing indexing = Indexing::automatic);

  /// Calls f(i, j) once for every unordered pair with |xi - xj| < ri + rj + skin. With `parts`
  /// > 1, only the pairs of part `part`: the parts 0 .. parts - 1 together report every pair
  /// once, and may be searched on threads at once (each a share of the spheres and of each
  /// level's entries).
  template <class F>
  void for_each_pair(F&& f, std::size_t part = 0, std::size_t parts = 1) const;

  std::size_t level_count() const { return levels_.size(); }
  /// Number of spheres stored on level l.
  std::size_t level_population(std::size_t l) const { return levels_[l].population; }
  double level_cell_size(std::size_t l) const { return levels_[l].cell; }
  /// Whether level l is indexed directly (true) or hashed.
  bool level_is_dense(std::size_t l) const { return levels_[l].dense; }
  /// Whether the pairs between levels fine < coarse are searched from the coarse spheres.
  bool searched_from_coarse(std::size_t fine, std::size_t coarse) const {
    return from_coarse_[fine * levels_.size() + coarse] != 0;
  }

 private:
  // A cell is identified by its integer coordinates on its level, packed 21 bits each into
  // one 64-bit key (coordinates count from the domain's lower corner, so they are >= 0).
  using Cell = std::array<std::int64_t, 3>;
  using Key = std::uint64_t;
  static constexpr int kBits = 21;
  static constexpr std::int64_t kMaxCoordinate = (std::int64_t{1} << kBits) - 1;
  static_assert(static_cast<double>(kMaxCoordinate) == limits::kGridCells, "validate() refuses scenes that do not fit the grid");

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
    bool dense = false;  ///< slots are cells (cx + nx (cy + ny cz)), not hash buckets
    std::int64_t nx = 0, ny = 0, nz = 0;  ///< dense: cells per axis
    std::vector<std::uint32_t> start;  ///< entries of slot b: [start[b], start[b + 1])
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
  /// Dense levels: the slot of cell (cx, cy, cz), which must lie inside the level's box.
  static std::size_t dense_slot(std::int64_t cx, std::int64_t cy, std::int64_t cz, const Level& L) {
    return static_cast<std::size_t>(cx + L.nx * (cy + L.ny * cz));
  }

  std::span<const Vec3> x_;
  std::span<const double> r_;
  double skin_ = 0.0;
  Vec3 origin_ = Vec3::Zero();
  std::vector<Level> levels_;
  std::vector<int> level_of_;  ///< level of each sphere
  std::vector<Key> cell_;      ///< cell of each sphere on its own level
  std::vector<std::uint8_t> from_coarse_;  ///< [fine * levels + coarse]: see searched_from_coarse()

  void choose_search_directions(const Vec3& extent);
};

template <class F>
void HierarchicalGrid::for_each_pair(F&& f, std::size_t part, std::size_t parts) const {
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
  // Calls `visit(entry)` for every sphere stored in cell c of hashed level L.
  const auto scan = [](const Level& L, Key c, auto&& visit) {
    const std::size_t b = bucket(c, L);
    for (std::uint32_t k = L.start[b], end = L.start[b + 1]; k < end; ++k)
      if (L.entries[k].cell == c) visit(L.entries[k]);
  };
  // Dense level L: every sphere in cells x0..x1 of row (cy, cz), x clipped to the box.
  const auto scan_row = [](const Level& L, std::int64_t x0, std::int64_t x1, std::int64_t cy, std::int64_t cz,
                           auto&& visit) {
    x0 = std::max<std::int64_t>(x0, 0);
    x1 = std::min(x1, L.nx - 1);
    if (x0 > x1 || cy < 0 || cy >= L.ny || cz < 0 || cz >= L.nz) return;
    const std::size_t row = dense_slot(0, cy, cz, L);
    for (std::uint32_t k = L.start[row + static_cast<std::size_t>(x0)], end = L.start[row + static_cast<std::size_t>(x1) + 1];
         k < end; ++k)
      visit(L.entries[k]);
  };
  const auto share = [&](std::size_t count, std::size_t t) { return count * t / parts; };
  for (int i = static_cast<int>(share(static_cast<std::size_t>(n), part)), i_end = static_cast<int>(share(static_cast<std::size_t>(n), part + 1));
       i < i_end; ++i) {
    const Vec3 xi = x_[i];
    const double ri_skin = r_[i] + skin_;
    const auto test = [&](const Entry& e) {
      const double s = ri_skin + e.r;
      if ((xi - e.x).squaredNorm() < s * s) f(i, e.id);
    };
    const auto test_later = [&](const Entry& e) {
      if (e.id > i) test(e);
    };
    const int li = level_of_[i];
    const Level& L = levels_[li];
    const Cell ci = cell_of(xi, L);
    if (L.dense) {
      // Own cell (pairs j > i), then the half stencil as rows: (+1, 0, 0), then x - 1 .. x + 1
      // of rows (y + 1, z), (y - 1, z + 1), (y, z + 1) and (y + 1, z + 1).
      scan_row(L, ci[0], ci[0], ci[1], ci[2], test_later);
      scan_row(L, ci[0] + 1, ci[0] + 1, ci[1], ci[2], test);
      scan_row(L, ci[0] - 1, ci[0] + 1, ci[1] + 1, ci[2], test);
      for (int dy = -1; dy <= 1; ++dy) scan_row(L, ci[0] - 1, ci[0] + 1, ci[1] + dy, ci[2] + 1, test);
    } else {
      // Same level, own cell.
      scan(L, cell_[i], test_later);
      // Same level, forward neighbours (coordinates are >= 0; a stencil cell at -1 is empty).
      for (const auto& o : kHalfStencil) {
        const std::int64_t cx = ci[0] + o[0], cy = ci[1] + o[1], cz = ci[2] + o[2];
        if (cx < 0 || cy < 0 || cz < 0) continue;
        scan(L, pack(cx, cy, cz), test);
      }
    }
    // Coarser levels searched from this side: the cells touched by this sphere's search box.
    for (std::size_t lc = static_cast<std::size_t>(li) + 1; lc < levels_.size(); ++lc) {
      const Level& C = levels_[lc];
      if (C.population == 0 || searched_from_coarse(static_cast<std::size_t>(li), lc)) continue;
      const double range = ri_skin + C.r_max;
      const Cell lo = cell_of(xi - Vec3::Constant(range), C);
      const Cell hi = cell_of(xi + Vec3::Constant(range), C);
      for (std::int64_t cz = lo[2]; cz <= hi[2]; ++cz)
        for (std::int64_t cy = lo[1]; cy <= hi[1]; ++cy) {
          if (C.dense) {
            scan_row(C, lo[0], hi[0], cy, cz, test);
          } else {
            for (std::int64_t cx = lo[0]; cx <= hi[0]; ++cx) scan(C, pack(cx, cy, cz), test);
          }
        }
    }
  }
  // The other pairs of levels, from the coarse side: each sphere j of level lc against the dense
  // rows of level lf within its reach. The test is the one above with the finer sphere as i.
  for (std::size_t lc = 1; lc < levels_.size(); ++lc)
    for (std::size_t k = share(levels_[lc].entries.size(), part), k_end = share(levels_[lc].entries.size(), part + 1); k < k_end; ++k)
      for (std::size_t lf = 0; lf < lc; ++lf) {
        const Entry& ej = levels_[lc].entries[k];
        if (!searched_from_coarse(lf, lc)) continue;
        const Level& L = levels_[lf];
        const double range = ej.r + skin_ + L.r_max;
        const Cell lo = cell_of(ej.x - Vec3::Constant(range), L);
        const Cell hi = cell_of(ej.x + Vec3::Constant(range), L);
        for (std::int64_t cz = lo[2]; cz <= hi[2]; ++cz)
          for (std::int64_t cy = lo[1]; cy <= hi[1]; ++cy)
            scan_row(L, lo[0], hi[0], cy, cz, [&](const Entry& e) {
              const double s = (e.r + skin_) + ej.r;
              if ((e.x - ej.x).squaredNorm() < s * s) f(e.id, ej.id);
            });
      }
}

}  // namespace softpack
