#include "sim/active_set.hpp"

#include <algorithm>

#include "forces/contact_walk.hpp"

namespace softpack {

ActiveSet::ActiveSet(const ActiveSetDef& def, std::size_t spheres)
    : def_(def),
      asleep_(spheres, 0),
      scale_(spheres, 0.0),
      wake_limit_(spheres, 0.0),
      frozen_F_(spheres, Vec3::Zero()),
      frozen_T_(spheres, Vec3::Zero()) {
  index();
}

void ActiveSet::index() {
  awake_list_.clear(), sleeping_list_.clear();
  for (std::size_t i = 0; i < asleep_.size(); ++i) (asleep_[i] ? sleeping_list_ : awake_list_).push_back(static_cast<std::int32_t>(i));
}

void ActiveSet::add_frozen(Particles& p) const {
  for (const std::int32_t i : sleeping_list_) p.F[i] += frozen_F_[i];
  if (p.rotates())
    for (const std::int32_t i : sleeping_list_) p.T[i] += frozen_T_[i];
}

void ActiveSet::rebuild(World& world, ContactLists& lists, ForceField& forces) {
  asleep_moved_ = {};          // every sphere is where the new lists were built
  lists.family[0].pairs.masked = false;  // a new numbering: update() starts from nothing frozen
  std::fill(frozen_F_.begin(), frozen_F_.end(), Vec3::Zero());
  std::fill(frozen_T_.begin(), frozen_T_.end(), Vec3::Zero());
  update(world, lists, forces);
}

std::size_t ActiveSet::sleep(World& world, ContactLists& lists, ForceField& forces, const std::vector<Vec3>& x_at_build) {
  // Each sphere's scale: the sum of its contacts' normal forces (Eq. 3).
  Particles& p = world.p;
  std::fill(scale_.begin(), scale_.end(), 0.0);
  if (forces.active())
    for_each_closed_contact(world, lists, forces, [&](const ClosedContact& c) {
      const double Fn = c.Fn();
      scale_[static_cast<std::size_t>(c.i)] += Fn;
      if (c.j >= 0) scale_[static_cast<std::size_t>(c.j)] += Fn;
    });
  const double v2 = def_.sleep_speed * def_.sleep_speed;
  std::size_t fell = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (asleep_[i] || p.is_driven(i)) continue;
    const double F2 = (def_.sleep_force * scale_[i]) * (def_.sleep_force * scale_[i]);
    if (!(p.F[i].squaredNorm() <= F2 && p.v[i].squaredNorm() <= v2)) continue;
    if (p.rotates() && p.inv_I[i] > 0.0) {  // a locked spin's torque is held by the lock
      const double r2 = p.r[i] * p.r[i];
      if (!(p.T[i].squaredNorm() <= F2 * r2 && p.w[i].squaredNorm() * r2 <= v2)) continue;
      p.w[i].setZero();
    }
    p.v[i].setZero();
    asleep_[i] = 1;
    wake_limit_[i] = def_.wake_force * scale_[i];
    asleep_moved_.add((p.x[i] - x_at_build[i]).squaredNorm());
    ++fell;
  }
  if (fell > 0) {
    sleeping_ += fell;
    update(world, lists, forces);
  }
  return fell;
}

std::size_t ActiveSet::wake(World& world, ContactLists& lists, ForceField& forces) {
  if (sleeping_ == 0) return 0;
  const Particles& p = world.p;
  std::size_t woke = 0;
  for (const std::int32_t k : sleeping_list_) {
    const auto i = static_cast<std::size_t>(k);
    const double F2 = wake_limit_[i] * wake_limit_[i];
    bool up = p.F[i].squaredNorm() > F2 || p.is_driven(i);
    if (!up && p.rotates() && p.inv_I[i] > 0.0) up = p.T[i].squaredNorm() > F2 * p.r[i] * p.r[i];
    if (!up) continue;
    asleep_[i] = 0;
    ++woke;
  }
  if (woke > 0) {
    sleeping_ -= woke;
    update(world, lists, forces);
  }
  return woke;
}

void ActiveSet::wake_all(ContactLists& lists) {
  std::fill(asleep_.begin(), asleep_.end(), 0);
  std::fill(frozen_F_.begin(), frozen_F_.end(), Vec3::Zero());
  std::fill(frozen_T_.begin(), frozen_T_.end(), Vec3::Zero());
  sleeping_ = 0;
  asleep_moved_ = {};
  index();
  lists.family[0].pairs.masked = false;
  lists.family[0].pairs.live.clear();
}

void ActiveSet::update(World& world, ContactLists& lists, ForceField& forces) {
  PairList& pl = lists.family[0].pairs;
  const std::size_t n = pl.size();
  if (sleeping_ == 0) {  // nothing frozen: the loop evaluates every pair
    wake_all(lists);
    return;
  }
  const bool fresh = !pl.masked;  // nothing frozen yet in this numbering
  if (fresh) awake_.assign(n, 1);
  to_frozen_.assign(n, 0), to_live_.assign(n, 0);
  pl.live.clear();
  bool any_frozen = false, any_live = false;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint8_t now = asleep_[pl.i[k]] && asleep_[pl.j[k]] ? 0 : 1;
    to_frozen_[k] = awake_[k] && !now;
    to_live_[k] = !awake_[k] && now;
    any_frozen = any_frozen || to_frozen_[k];
    any_live = any_live || to_live_[k];
    awake_[k] = now;
    if (now) pl.live.push_back(static_cast<std::int32_t>(k));
  }
  pl.masked = true;
  Vec3* const T = world.p.rotates() ? frozen_T_.data() : nullptr;
  // The pairs that leave the frozen side give back the forces they added.
  if (any_live) forces.add_pair_forces(world, pl, to_live_.data(), -1.0, frozen_F_.data(), T);
  if (any_frozen) forces.add_pair_forces(world, pl, to_frozen_.data(), 1.0, frozen_F_.data(), T);
  index();
  for (const std::int32_t i : awake_list_) frozen_F_[i].setZero(), frozen_T_[i].setZero();  // exactly, not by cancellation
}

}  // namespace softpack
