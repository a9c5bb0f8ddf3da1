// The contact forces of a scene: the normal law it declares (forces/normal_law.hpp) with its
// effects, the constants two materials share (Eq. 4, Eq. 6, Coulomb) and the damping, and the
// compiled force loops. The neighbour lists ask it for the constants of each new contact; every
// step it adds the forces of the touching ones.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/effects.hpp"
#include "forces/normal_law.hpp"
#include "forces/soft_contacts.hpp"
#include "neighbor/contact_list.hpp"
#include "neighbor/neighbours.hpp"
#include "scene/scene_def.hpp"
#include "state/world.hpp"

namespace softpack {

class ForceField {
 public:
  /// InputError "effects.normal: ..." when the scene names a law that is not registered.
  explicit ForceField(const SceneDef& scene);

  /// False when the scene declares no normal law: then nothing touches anything.
  bool active() const { return law_ != nullptr; }
  const NormalLaw& law() const { return *law_; }
  const Effects& effects() const { return fx_; }
  /// The soft-particle contacts (forces/soft_contacts.hpp), or null when the scene has none.
  const SoftContacts* soft() const { return soft_ ? &*soft_ : nullptr; }

  /// Adds the force (and torque) of every touching contact to the spheres and the wall loads,
  /// advances the springs of touching contacts by `spring_dt` and clears those of open ones.
  void add_contact_forces(World& world, ContactLists& lists, double spring_dt);
  /// `sign` times the forces of the touching pairs marked in `mask` into F and T (the active
  /// set's frozen sums, sim/active_set.hpp; springs neither advanced nor written).
  void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T);

  /// The constants of the contacts a neighbour rebuild added.
  void set_constants(const World& world, ContactLists& lists, const NewContacts& added) const;
  ContactConstants<double> pair_constants(const Particles& p, int i, int j) const;
  /// A sphere against a wall of material `wall_material` (infinite mass), reduced radius R12.
  ContactConstants<double> wall_constants(const Particles& p, int i, int wall_material, double R12) const;

 private:
  ContactConstants<double> constants(std::size_t mm, double R12, double m12, double inv_mt) const;

  const NormalLaw* law_ = nullptr;
  Effects fx_;
  std::unique_ptr<ForceLoops> loops_;
  double zeta_ = 0.0, tangential_ratio_ = 1.0;
  std::size_t materials_ = 0;
  std::vector<double> D_, Dt_, mu_;  ///< material pair constants, index a * materials + b
  std::vector<std::int32_t> closed_;  ///< scratch of the loops
  std::optional<SoftContacts> soft_;  ///< effects.soft_particles only
};

}  // namespace softpack
