// The spheres of a world (state/world.hpp), stored as parallel arrays (structure of arrays). Arrays that belong to an effect
// the scene did not declare stay empty: no angular state without rotation, no kinematic flags
// without drivers.
#pragma once
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace softpack {

/// The family of a soft-particle's contacts (effects.soft_particles).
inline constexpr std::uint8_t kSoftParticleFamily = 1;

struct Particles {
  std::vector<Vec3> x;       ///< centre [m]
  std::vector<Vec3> v;       ///< velocity [m/s]
  std::vector<Vec3> F;       ///< net force of the last force evaluation [N]
  std::vector<double> r;     ///< radius [m]
  std::vector<double> m;     ///< mass [kg]
  std::vector<double> inv_m;
  std::vector<int> body;      ///< soft-particle id, or kNoBody
  std::vector<int> material;  ///< index into the scene's materials

  // Rotation effect only.
  std::vector<Vec3> w;        ///< angular velocity [rad/s]
  std::vector<Vec3> T;        ///< torque [N m]
  std::vector<double> inv_I;  ///< 1 / moment of inertia, I = 2/5 m r^2

  // Drivers only: 1 while a kinematic driver prescribes the sphere's motion.
  std::vector<std::uint8_t> driven;

  // The contact model of each sphere's contacts (neighbor/contact_list.hpp ContactLists): the
  // scene's (0), or the soft-particle model (kSoftParticleFamily) for a soft-particle. Empty:
  // every sphere's is the scene's.
  std::vector<std::uint8_t> family;

  std::size_t size() const { return x.size(); }
  bool rotates() const { return !w.empty(); }
  bool is_driven(std::size_t i) const { return !driven.empty() && driven[i] != 0; }
  std::size_t family_of(std::size_t i) const { return family.empty() ? 0 : family[i]; }
};

}  // namespace softpack
