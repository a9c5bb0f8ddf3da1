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
  for (const int j : L.members) {
    int& head = L.head[bucket(cell_[j], L)];
    next_[j] = head;
    head = j;
  }
}

std::size_t InsertionGrid::level_for(double r) const {
  std::size_t l = 0;
  while (l + 1 < levels_.size() && levels_[l].cell < 2.0 * r) ++l;
  return l;
}

void InsertionGrid::link(int id, std::size_t l) {
  Level& L = levels_[l];
  const Vec3& x = x_[id];
  level_of_[id] = static_cast<int>(l);
  cell_[id] = pack(coordinate(x.x(), L), coordinate(x.y(), L), coordinate(x.z(), L));
  member_index_[id] = L.members.size();
  L.members.push_back(id);
  ++L.population;
  L.r_max = std::max(L.r_max, r_[id]);
  if (L.population * 2 > L.head.size()) {
    rehash(L);  // includes the new sphere
  } else {
    int& head = L.head[bucket(cell_[id], L)];
    next_[id] = head;
    head = id;
  }
}

void InsertionGrid::unlink(int id) {
  Level& L = levels_[level_of_[id]];
  for (int* j = &L.head[bucket(cell_[id], L)]; *j != -1; j = &next_[*j])
    if (*j == id) {
      *j = next_[id];
      break;
    }
  next_[id] = -1;
  const int last = L.members.back();
  L.members[member_index_[id]] = last;
  member_index_[last] = member_index_[id];
  L.members.pop_back();
  --L.population;
  level_of_[id] = -1;  // L.r_max stays an upper bound
}

int InsertionGrid::insert(const Vec3& x, double r) {
  const int id = static_cast<int>(x_.size());
  x_.push_back(x);
  r_.push_back(r);
  level_of_.push_back(-1);
  cell_.push_back(0);
  next_.push_back(-1);
  member_index_.push_back(0);
  link(id, level_for(r));
  return id;
}

void InsertionGrid::set_radius(int id, double r) {
  r_[id] = r;
  const std::size_t l = level_for(r);
  if (l > static_cast<std::size_t>(level_of_[id])) {
    unlink(id);  // grown beyond its cell: to the level that holds it
    link(id, l);
  } else {
    Level& L = levels_[level_of_[id]];
    L.r_max = std::max(L.r_max, r);  // queries reach every sphere whose radius is <= r_max
  }
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

std::pair<double, int> InsertionGrid::nearest_centre(const Vec3& x, int self, double search) const {
  std::pair<double, int> best{std::numeric_limits<double>::infinity(), -1};
  for (const Level& L : levels_) {
    if (L.population == 0) continue;
    scan(L, x, search, [&](int j) {
      if (j == self) return false;
      const double d = (x - x_[j]).norm();
      if (d < search && (d < best.first || (d == best.first && j < best.second))) best = {d, j};
      return false;
    });
  }
  return best;
}

}  // namespace softpack
