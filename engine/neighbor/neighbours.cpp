#include "neighbor/neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"

namespace softpack {

Neighbours::Neighbours(const NeighborDef& def, const World& world, const std::vector<std::size_t>& constants, bool friction,
                       std::vector<std::vector<int>> shell_members)
    : def_(def), friction_(friction), shell_members_(std::move(shell_members)) {
  double r_min = std::numeric_limits<double>::max();
  for (double r : world.p.r) r_min = std::min(r_min, r);
  skin_ = def.skin * r_min;
  // Family 0 always exists (empty without a contact law: nothing is listed).
  listing_ = !constants.empty();
  lists_.family.resize(std::max<std::size_t>(1, constants.size()));
  for (std::size_t f = 0; f < lists_.family.size(); ++f) {
    ContactFamily& l = lists_.family[f];
    l.pairs.k.resize(listing_ ? constants[f] : 0, 0);
    l.planes.resize(world.planes.size());
    l.shells.resize(world.shells.size());
    for (auto* walls : {&l.planes, &l.shells})
      for (WallList& w : *walls) w.k.resize(listing_ ? constants[f] : 0, 0);
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

std::vector<NewContacts> Neighbours::rebuild(const World& world) {
  const Particles& p = world.p;
  const std::size_t n = p.size(), families = lists_.family.size();
  std::vector<NewContacts> added(families);
  if (listing_) {
    // Pairs as (i, j) with i < j, sorted: the grid searched by parts on the threads, a counting
    // sort by i, then each sphere's few partners sorted by j (on the threads by shares of i).
    // The order the parts report their pairs in does not matter: the sort's is the only one.
    grid_.build(p.x, p.r, skin_, def_.level_ratio);
    const auto parts = static_cast<std::size_t>(parallel::threads_for(n));
    found_.resize(parts);
    parallel::for_each_block(parts, [&](std::size_t t) {
      found_[t].clear();
      grid_.for_each_pair([&](int i, int j) { found_[t].push_back(std::minmax(i, j)); }, t, parts);
    });
    first_.assign(n + 1, 0);
    for (const auto& found : found_)
      for (const auto& [a, b] : found) ++first_[static_cast<std::size_t>(a) + 1];
    for (std::size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
    std::vector<PairEntry> fresh(first_[n]);
    for (const auto& found : found_)
      for (const auto& [a, b] : found) fresh[first_[static_cast<std::size_t>(a)]++] = PairEntry{a, b, p.r[a] + p.r[b]};
    // Sphere i's pairs are now [first_[i - 1], first_[i]) (from 0 for i = 0).
    parallel::for_each_share(n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        std::sort(fresh.begin() + static_cast<std::ptrdiff_t>(i == 0 ? 0 : first_[i - 1]), fresh.begin() + static_cast<std::ptrdiff_t>(first_[i]),
                  [](const PairEntry& a, const PairEntry& b) { return a.j < b.j; });
    });
    // Each pair to the higher family of its spheres; the order (i, j) is kept in each.
    const auto family_of_pair = [&](const PairEntry& e) {
      return std::max(p.family_of(static_cast<std::size_t>(e.i)), p.family_of(static_cast<std::size_t>(e.j)));
    };
    if (families == 1) {
      added[0].pairs = lists_.family[0].pairs.replace(fresh, friction_);
    } else {
      std::vector<std::vector<PairEntry>> split(families);
      for (const PairEntry& e : fresh) split[family_of_pair(e)].push_back(e);
      for (std::size_t f = 0; f < families; ++f) added[f].pairs = lists_.family[f].pairs.replace(split[f], friction_);
    }
    // The spheres near each plane, in ascending order: each share's on its thread, then the
    // shares in order.
    std::vector<std::vector<std::int32_t>> near(families);
    near_.resize(parts);
    for (std::size_t w = 0; w < world.planes.size(); ++w) {
      const PlaneWall& plane = world.planes[w];
      parallel::for_each_block(parts, [&](std::size_t t) {
        near_[t].resize(families);
        for (auto& l : near_[t]) l.clear();
        for (std::size_t i = parallel::share_begin(n, t, parts), end = parallel::share_begin(n, t + 1, parts); i < end; ++i)
          if (plane.distance(p.x[i]) - p.r[i] < skin_) near_[t][p.family_of(i)].push_back(static_cast<std::int32_t>(i));
      });
      for (std::size_t f = 0; f < families; ++f) {
        near[f].clear();
        for (const auto& of_share : near_) near[f].insert(near[f].end(), of_share[f].begin(), of_share[f].end());
        added[f].planes.push_back(lists_.family[f].planes[w].replace(near[f], friction_));
      }
    }
    for (std::size_t w = 0; w < world.shells.size(); ++w) {
      const SphericalShell& s = world.shells[w];
      for (auto& l : near) l.clear();
      for (int i : shell_members_[w])
        if (s.radius - (p.x[i] - s.centre).norm() - p.r[i] < skin_) near[p.family_of(static_cast<std::size_t>(i))].push_back(i);
      for (std::size_t f = 0; f < families; ++f) added[f].shells.push_back(lists_.family[f].shells[w].replace(near[f], friction_));
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
