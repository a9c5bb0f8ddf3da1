// The contact forces of a scene: one contact model per family of contacts (neighbor/contact_list.hpp
// ContactLists): family 0 the model the scene declares (effects.normal, forces/contact_models.hpp),
// family 1 the soft-particle model when the scene has soft-particles (effects.soft_particles).
// The neighbour lists ask it for the constants of each new contact; every step it adds the forces
// of the touching ones, family by family, through the same loops.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/effects.hpp"
#include "forces/contact_models.hpp"
#include "neighbor/contact_list.hpp"
#include "neighbor/neighbours.hpp"
#include "scene/scene_def.hpp"
#include "state/world.hpp"

namespace softpack {

class ForceField {
 public:
  /// InputError "effects.normal: ..." when the scene names a model that is not registered.
  explicit ForceField(const SceneDef& scene);

  /// False when the scene declares no normal law: then nothing touches anything.
  bool active() const { return !models_.empty(); }
  const Effects& effects() const { return fx_; }
  /// The model of family f (0: the scene's; 1: the soft-particles').
  const SceneModel& model(std::size_t f) const { return *models_[f]; }
  /// The number of models (0 without a normal law; the lists then have one empty family).
  std::size_t models() const { return models_.size(); }
  /// The number of constants of each family's model (what the lists are made for).
  std::vector<std::size_t> constants() const;
  /// How far contacts went beyond the range their law was measured on, over all families.
  RangeStats range() const;

  /// Adds the force (and torque) of every touching contact to the spheres and the wall loads,
  /// advances the springs of touching contacts by `spring_dt` and clears those of open ones.
  void add_contact_forces(World& world, ContactLists& lists, double spring_dt);
  /// `sign` times the forces of the touching pairs of family 0 marked in `mask` into F and T
  /// (the active set's frozen sums, sim/active_set.hpp; springs neither advanced nor written).
  void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T);

  /// The constants of the contacts a neighbour rebuild added, family by family.
  void set_constants(const World& world, ContactLists& lists, const std::vector<NewContacts>& added) const;

 private:
  Effects fx_;
  std::size_t materials_ = 0;
  std::vector<std::unique_ptr<SceneModel>> models_;
  std::vector<std::int32_t> closed_;  ///< scratch of the loops
};

}  // namespace softpack
