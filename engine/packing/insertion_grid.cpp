#include "packing/insertion_grid.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace softpack {

InsertionGrid::InsertionGrid(double r_min, double r_max, double level_ratio) {
  if (!(r_min > 0.0 && r_max >= r_min && level_ratio > 1.0))
    throw std::invalid_argument("InsertionGrid: need 0 < r_min <= r_max and level_ratio > 1");
  for (double c = 2.0 * r_min;; c *= level_ratio) {
    Level L;
    L.cell = c;
    L.inv_cell = 1.0 / c;
    L.head.assign(16, -1);
    L.shift = 64 - 4;
    levels_.push_back(std::move(L));
    if (c >= 2.0 * r_max) break;
  }
}

void InsertionGrid::rehash(Level& L) {
  const std::size_t buckets = L.head.size() * 4;
  L.head.assign(buckets, -1);
  L.shift = 64 - std::countr_zero(buckets);
  const int level = static_cast<int>(&L - levels_.data());
  for (int j = static_cast<int>(x_.size()) - 1; j >= 0; --j) {
    if (level_of_[j] != level) continue;
    int& head = L.head[bucket(cell_[j], L)];
    next_[j] = head;
    head = j;
  }
}

int InsertionGrid::insert(const Vec3& x, double r) {
  std::size_t l = 0;
  while (l + 1 < levels_.size() && levels_[l].cell < 2.0 * r) ++l;
  Level& L = levels_[l];
  const int id = static_cast<int>(x_.size());
  x_.push_back(x);
  r_.push_back(r);
  level_of_.push_back(static_cast<int>(l));
  cell_.push_back(pack(coordinate(x.x(), L), coordinate(x.y(), L), coordinate(x.z(), L)));
  next_.push_back(-1);
  ++L.population;
  L.r_max = std::max(L.r_max, r);
  if (L.population * 2 > L.head.size()) {
    rehash(L);  // includes the new sphere
  } else {
    int& head = L.head[bucket(cell_[id], L)];
    next_[id] = head;
    head = id;
  }
  return id;
}

void InsertionGrid::set_radius(int id, double r) {
  r_[id] = r;
  Level& L = levels_[level_of_[id]];
  L.r_max = std::max(L.r_max, r);  // queries reach every sphere whose radius is <= r_max
}

bool InsertionGrid::overlaps(const Vec3& x, double r) const {
  // Coarse levels first: a large stored sphere is the likeliest obstacle.
  for (std::size_t l = levels_.size(); l-- > 0;) {
    const Level& L = levels_[l];
    if (L.population == 0) continue;
    const bool hit = scan(L, x, r + L.r_max, [&](int j) {
      const double s = r + r_[j];
      return (x - x_[j]).squaredNorm() < s * s;
    });
    if (hit) return true;
  }
  return false;
}

double InsertionGrid::nearest_gap(const Vec3& x, double r, int self, double search) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Level& L : levels_) {
    if (L.population == 0) continue;
    scan(L, x, r + L.r_max + search, [&](int j) {
      if (j == self) return false;
      const double gap = (x - x_[j]).norm() - r - r_[j];
      if (gap < search) best = std::min(best, gap);
      return false;
    });
  }
  return best;
}

}  // namespace softpack
