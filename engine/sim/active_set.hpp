// The active set (scene/active_set_def.hpp): free spheres at rest sleep until a force wakes them.
//
// A sleeping sphere has v = w = 0 and is skipped by the integrator; the force loop skips its
// contacts with other sleeping spheres (PairList::awake), whose forces cannot change while
// neither sphere moves (the positions are fixed, the relative velocity is zero, so the springs
// do not advance). Their sum per sphere, the frozen force and torque, is kept here and starts
// each step's F and T of a sleeping sphere, so its net force is always the full one: contacts
// with awake spheres and with walls are evaluated every step.
//
// The set changes at two moments, and each change updates the sums by the pairs that changed
// side (forces/contact_models.hpp SceneModel::add_pair_forces, with the same law and the same bits as the loop):
//
//   sleep   at each check (every check_interval, and after each stop of the paper protocol):
//           a free sphere with |F|, |T|/r <= sleep_force x S and |v|, |w| r <= sleep_speed
//           falls asleep, S the sum of its contacts' normal forces (a grain pushed by one
//           contact, a rattler, has |F| = S: it is not at rest and does not sleep)
//   wake    at every step, once the forces are known: a sleeping sphere whose |F| or |T|/r
//           exceeds wake_force x S (S when it fell asleep) wakes (before its half kick, so it
//           moves this step)
//
// A neighbour rebuild renumbers the pairs: the mask and sums are then made anew.
#pragma once
#include <cstdint>
#include <vector>

#include "forces/force_field.hpp"
#include "integrate/velocity_verlet.hpp"
#include "neighbor/contact_list.hpp"
#include "scene/active_set_def.hpp"
#include "state/world.hpp"

namespace softpack {

class ActiveSet {
 public:
  /// Every sphere awake; `def` is validated by the caller (scene/validate.hpp).
  ActiveSet(const ActiveSetDef& def, std::size_t spheres);

  const ActiveSetDef& def() const { return def_; }
  bool asleep(std::size_t i) const { return asleep_[i] != 0; }
  std::size_t sleeping() const { return sleeping_; }
  /// |F| and |T| / r of sleeping sphere i stay at or below this [N] (it wakes otherwise).
  double wake_threshold(std::size_t i) const { return wake_limit_[i]; }
  /// The frozen force and torque of sphere i (zero while it is awake).
  const Vec3& frozen_force(std::size_t i) const { return frozen_F_[i]; }
  /// What the integrator moves: the awake spheres, and the sleepers' largest displacements.
  Movers movers() const { return {&awake_list_, asleep_moved_}; }

  /// Before the contact loops of a step: F and T of each sleeping sphere start from its frozen sums.
  void add_frozen(Particles& p) const;
  /// After a neighbour rebuild (new pair numbering): the mask and the frozen sums anew.
  void rebuild(World& world, ContactLists& lists, ForceField& forces);
  /// A sleep check; `x_at_build`: the positions of the last neighbour build (a sleeper's
  /// displacement since then still counts towards the skin). Returns how many fell asleep.
  std::size_t sleep(World& world, ContactLists& lists, ForceField& forces, const std::vector<Vec3>& x_at_build);
  /// After the forces of a step: wakes the sleeping spheres above the threshold, and every driven
  /// one. Returns how many woke.
  std::size_t wake(World& world, ContactLists& lists, ForceField& forces);
  /// Wakes every sphere and leaves the lists as without an active set.
  void wake_all(ContactLists& lists);

  /// Counts one step: sphere-steps integrated and in all (their ratio is the work saved).
  void count_step(std::size_t spheres) {
    sphere_steps_ += static_cast<double>(spheres);
    awake_sphere_steps_ += static_cast<double>(spheres - sleeping_);
  }
  double sphere_steps() const { return sphere_steps_; }
  double awake_sphere_steps() const { return awake_sphere_steps_; }

 private:
  /// After asleep_ changed: PairList::live and the frozen sums, by the pairs that changed side.
  void update(World& world, ContactLists& lists, ForceField& forces);
  /// The lists of awake and sleeping spheres from asleep_.
  void index();

  ActiveSetDef def_;
  std::vector<std::uint8_t> asleep_;
  std::vector<double> scale_;       ///< per sphere: the sum of its contacts' normal forces at the last check [N]
  std::vector<double> wake_limit_;  ///< per sleeping sphere: wake_force x its scale when it fell asleep [N]
  std::vector<Vec3> frozen_F_, frozen_T_;
  std::vector<std::uint8_t> awake_;                ///< per pair of the masked list: 1 if live
  std::vector<std::uint8_t> to_frozen_, to_live_;  ///< scratch of update(), one byte per pair
  std::vector<std::int32_t> awake_list_, sleeping_list_;
  Neighbours::LargestTwo asleep_moved_;  ///< of the sleepers (and some since woken: an upper bound)
  std::size_t sleeping_ = 0;
  double sphere_steps_ = 0.0, awake_sphere_steps_ = 0.0;
};

}  // namespace softpack
