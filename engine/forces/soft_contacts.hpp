// The contacts of soft-particles (effects.soft_particles): each one through the measured laws of
// contact/soft_particle_law.hpp, one contact at a time (they are few: a soft-particle replaces a
// thousand grains). Geometry and conventions as the solid spheres' contacts
// (forces/pair_contacts.hpp, forces/wall_contacts.hpp): body 1 is sphere i (the soft-particle
// against a wall), the normal points from body 2 to body 1. A scene without soft-particles
// never builds one (ForceField holds none).
#pragma once
#include <memory>

#include "contact/soft_particle_law.hpp"
#include "neighbor/contact_list.hpp"
#include "scene/scene_def.hpp"
#include "state/world.hpp"

namespace softpack {

/// How far the soft-particle contacts went beyond the Δn the laws were measured on.
struct SoftContactStats {
  long beyond_range = 0;  ///< contact evaluations with Δn above the normal law's measured range
  double max_dn = 0.0;    ///< the largest Δn met
  int i = -1, j = -1;     ///< its spheres (j = -1: sphere i against plane `plane`)
  int plane = -1;
};

class SoftContacts {
 public:
  explicit SoftContacts(const SceneDef& scene);

  /// The constants of every soft contact (after each rebuild: they carry no history).
  void set_constants(const World& world, SoftLists& lists) const;
  /// Adds the forces of the touching soft contacts, advances their springs by `spring_dt` and
  /// clears those of open ones. NumericalError with `beyond_range: stop` when a contact's Δn
  /// leaves the measured range.
  void add_forces(World& world, SoftLists& lists, double spring_dt);
  const SoftContactStats& stats() const { return stats_; }
  const SoftParticlesDef& def() const { return *def_; }

 private:
  void count(double dn, int i, int j, int plane, const SoftContactConstants& k);

  std::unique_ptr<const SoftParticlesDef> def_;  // the constants point into its laws
  SoftEffects fx_;
  bool rotation_ = false, synchronized_ = false;
  SoftContactStats stats_;
};

}  // namespace softpack
