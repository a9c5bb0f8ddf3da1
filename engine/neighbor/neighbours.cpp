#include "neighbor/neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace softpack {

Neighbours::Neighbours(const NeighborDef& def, const World& world, bool normal, bool friction,
                       std::vector<std::vector<int>> shell_members)
    : def_(def), normal_(normal), friction_(friction), shell_members_(std::move(shell_members)) {
  double r_min = std::numeric_limits<double>::max();
  for (double r : world.p.r) r_min = std::min(r_min, r);
  skin_ = def.skin * r_min;
  lists_.planes.resize(world.planes.size());
  lists_.shells.resize(world.shells.size());
  if (!world.p.soft.empty()) {
    lists_.soft.emplace();
    lists_.soft->planes.resize(world.planes.size());
  }
}

bool Neighbours::need_rebuild(const World& world) const {
  double wall_disp = 0.0;
  for (std::size_t k = 0; k < world.planes.size(); ++k)
    wall_disp = std::max(wall_disp, (world.planes[k].point - plane_at_build_[k]).norm());
  for (std::size_t k = 0; k < world.shells.size(); ++k)
    wall_disp = std::max(wall_disp, (world.shells[k].centre - shell_at_build_[k]).norm());
  const double disp = std::sqrt(moved_.first);
  return disp + std::sqrt(moved_.second) >= skin_ || disp + wall_disp >= skin_;
}

NewContacts Neighbours::rebuild(const World& world) {
  const Particles& p = world.p;
  const std::size_t n = p.size();
  NewContacts added;
  if (normal_) {
    // Pairs as (i, j) with i < j, sorted: a counting sort by i, then each sphere's few partners
    // sorted by j.
    grid_.build(p.x, p.r, skin_, def_.level_ratio);
    found_.clear();
    first_.assign(n + 1, 0);
    grid_.for_each_pair([&](int i, int j) {
      const auto [a, b] = std::minmax(i, j);
      found_.emplace_back(a, b);
      ++first_[static_cast<std::size_t>(a) + 1];
    });
    for (std::size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
    std::vector<PairEntry> fresh(found_.size());
    for (const auto& [a, b] : found_) fresh[first_[a]++] = PairEntry{a, b, p.r[a] + p.r[b]};
    for (std::size_t i = 0, begin = 0; i < n; begin = first_[i++])
      std::sort(fresh.begin() + static_cast<std::ptrdiff_t>(begin), fresh.begin() + static_cast<std::ptrdiff_t>(first_[i]),
                [](const PairEntry& a, const PairEntry& b) { return a.j < b.j; });
    if (lists_.soft) {
      // A pair with a soft-particle goes to the soft lists; the order (i, j) is kept in both.
      std::vector<PairEntry> solid_pairs, soft_pairs;
      for (const PairEntry& e : fresh)
        (p.is_soft(static_cast<std::size_t>(e.i)) || p.is_soft(static_cast<std::size_t>(e.j)) ? soft_pairs : solid_pairs).push_back(e);
      fresh = std::move(solid_pairs);
      lists_.soft->pairs.replace(soft_pairs, friction_);
      added.soft = true;
    }
    added.pairs = lists_.pairs.replace(fresh, friction_);

    for (std::size_t w = 0; w < world.planes.size(); ++w) {
      std::vector<std::int32_t> near, near_soft;
      for (std::size_t i = 0; i < n; ++i)
        if (world.planes[w].distance(p.x[i]) - p.r[i] < skin_) (p.is_soft(i) ? near_soft : near).push_back(static_cast<std::int32_t>(i));
      added.planes.push_back(lists_.planes[w].replace(near, friction_));
      if (lists_.soft) lists_.soft->planes[w].replace(near_soft, friction_);
    }
    for (std::size_t w = 0; w < world.shells.size(); ++w) {
      const SphericalShell& s = world.shells[w];
      std::vector<std::int32_t> near;
      for (int i : shell_members_[w])
        if (s.radius - (p.x[i] - s.centre).norm() - p.r[i] < skin_) near.push_back(i);
      added.shells.push_back(lists_.shells[w].replace(near, friction_));
    }
  }
  x_at_build_ = p.x;
  plane_at_build_.clear();
  for (const auto& pl : world.planes) plane_at_build_.push_back(pl.point);
  shell_at_build_.clear();
  for (const auto& s : world.shells) shell_at_build_.push_back(s.centre);
  moved_ = {};
  ++rebuilds_;
  return added;
}

}  // namespace softpack
