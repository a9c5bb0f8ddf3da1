// The spheres of a world (state/world.hpp), stored as parallel arrays (structure of arrays). Arrays that belong to an effect
// the scene did not declare stay empty: no angular state without rotation, no kinematic flags
// without drivers.
#pragma once
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace softpack {

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

  // Soft-particle contacts only (effects.soft_particles): 1 for a soft-particle.
  std::vector<std::uint8_t> soft;

  std::size_t size() const { return x.size(); }
  bool rotates() const { return !w.empty(); }
  bool is_driven(std::size_t i) const { return !driven.empty() && driven[i] != 0; }
  bool is_soft(std::size_t i) const { return !soft.empty() && soft[i] != 0; }
};

}  // namespace softpack
