#include "neighbor/hierarchical_grid.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

namespace softpack {

void HierarchicalGrid::build(std::span<const Vec3> x, std::span<const double> r, double skin,
                             double level_ratio, Indexing indexing) {
  if (x.size() != r.size()) throw std::invalid_argument("HierarchicalGrid: x and r differ");
  if (!(level_ratio > 1.0)) throw std::invalid_argument("HierarchicalGrid: level_ratio <= 1");
  if (!(skin >= 0.0)) throw std::invalid_argument("HierarchicalGrid: skin < 0");
  x_ = x;
  r_ = r;
  skin_ = skin;
  const std::size_t n = x.size();
  levels_.clear();
  level_of_.assign(n, 0);
  cell_.resize(n);
  if (n == 0) return;

  double r_min = std::numeric_limits<double>::max(), r_max = 0.0;
  origin_ = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 x_max = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < n; ++i) {
    r_min = std::min(r_min, r[i]);
    r_max = std::max(r_max, r[i]);
    origin_ = origin_.cwiseMin(x[i] - Vec3::Constant(r[i]));
    x_max = x_max.cwiseMax(x[i] + Vec3::Constant(r[i]));
  }
  // Level cell sizes: c_0 = 2 r_min + skin, growing by level_ratio up to 2 r_max + skin.
  std::vector<double> cells{2.0 * r_min + skin};
  while (cells.back() < 2.0 * r_max + skin) cells.push_back(cells.back() * level_ratio);
  levels_.resize(cells.size());
  for (std::size_t l = 0; l < cells.size(); ++l) {
    levels_[l].cell = cells[l];
    levels_[l].inv_cell = 1.0 / cells[l];
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double d = 2.0 * r[i] + skin;
    const auto it = std::lower_bound(cells.begin(), cells.end(), d);
    const int l = static_cast<int>(std::min<std::ptrdiff_t>(it - cells.begin(),
                                                            static_cast<std::ptrdiff_t>(cells.size()) - 1));
    level_of_[i] = l;
    ++levels_[l].population;
    levels_[l].r_max = std::max(levels_[l].r_max, r[i]);
  }
  // 21-bit cell coordinates: the domain may span at most 2^21 cells of the finest level.
  const Vec3 extent = (x_max - origin_);
  if (extent.maxCoeff() * levels_[0].inv_cell >= static_cast<double>(kMaxCoordinate))
    throw std::invalid_argument("HierarchicalGrid: the domain spans more than 2^21 of the smallest cells");
  for (Level& L : levels_) {
    if (!L.population) continue;
    // The box of cells that holds every centre (cell_of of the far corner), if small enough.
    const Cell far = cell_of(x_max, L);
    L.nx = far[0] + 1, L.ny = far[1] + 1, L.nz = far[2] + 1;
    const double cells = static_cast<double>(L.nx) * static_cast<double>(L.ny) * static_cast<double>(L.nz);
    L.dense = indexing == Indexing::automatic &&
              cells <= kDenseCellsPerSphere * static_cast<double>(L.population) + 4096.0;
    if (L.dense) {
      L.start.assign(static_cast<std::size_t>(cells) + 1, 0);
    } else {
      const std::uint64_t buckets = std::bit_ceil(std::max<std::uint64_t>(16, 2 * L.population));
      L.shift = 64 - std::countr_zero(buckets);
      L.start.assign(buckets + 1, 0);
    }
    L.entries.resize(L.population);
  }
  choose_search_directions(extent);
  // Counting sort of each level's spheres by slot (stable: increasing index within a slot).
  std::vector<std::uint32_t> bucket_of(n);
  for (std::size_t k = 0; k < n; ++k) {
    Level& L = levels_[level_of_[k]];
    const Cell c = cell_of(x[k], L);
    cell_[k] = pack(c[0], c[1], c[2]);
    bucket_of[k] = static_cast<std::uint32_t>(L.dense ? dense_slot(c[0], c[1], c[2], L) : bucket(cell_[k], L));
    ++L.start[bucket_of[k] + 1];
  }
  for (Level& L : levels_)
    for (std::size_t b = 1; b < L.start.size(); ++b) L.start[b] += L.start[b - 1];
  std::vector<std::uint32_t> fill;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& L = levels_[l];
    if (!L.population) continue;
    fill.assign(L.start.begin(), L.start.end() - 1);
    for (std::size_t k = 0; k < n; ++k)
      if (level_of_[k] == static_cast<int>(l))
        L.entries[fill[bucket_of[k]]++] = Entry{x[k], r[k], cell_[k], static_cast<int>(k)};
  }
}

// Expected cost of the cross-level search between levels f < c, each way, in units of one
// distance test: a row (or, hashed, a cell) costs kRowCost tests of overhead, and a search box
// w cells wide holds w^3 cells of the searched level at its mean occupancy. The box is the
// largest a sphere of the searching level can need: r_max(f) + skin + r_max(c) on each side.
void HierarchicalGrid::choose_search_directions(const Vec3& extent) {
  constexpr double kRowCost = 2.0;
  const std::size_t nl = levels_.size();
  from_coarse_.assign(nl * nl, 0);
  const auto cells = [&](const Level& L) {
    return (extent.x() * L.inv_cell + 1.0) * (extent.y() * L.inv_cell + 1.0) * (extent.z() * L.inv_cell + 1.0);
  };
  for (std::size_t f = 0; f < nl; ++f)
    for (std::size_t c = f + 1; c < nl; ++c) {
      const Level &F = levels_[f], &C = levels_[c];
      if (!F.population || !C.population || !F.dense) continue;  // from the coarse side needs dense rows
      const double reach = 2.0 * (F.r_max + skin_ + C.r_max);
      const double wf = reach * C.inv_cell + 1.0, wc = reach * F.inv_cell + 1.0;
      const double nf = static_cast<double>(F.population), nc = static_cast<double>(C.population);
      const double from_fine = nf * ((C.dense ? kRowCost * wf * wf : kRowCost * wf * wf * wf) + wf * wf * wf * nc / cells(C));
      const double from_coarse = nc * (kRowCost * wc * wc + wc * wc * wc * nf / cells(F));
      from_coarse_[f * nl + c] = from_coarse < from_fine ? 1 : 0;
    }
}

}  // namespace softpack
