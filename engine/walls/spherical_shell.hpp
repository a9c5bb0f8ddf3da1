// The soft-particle's shell: an invisible, rigid, impenetrable spherical wall of radius Rs,
// of the same material as its grains, that confines the spheres of its own body from inside
// and ignores every other sphere (paper §4).
//
// A shell is kinematic (it stands still or a driver moves it) unless it has a mass: then it is
// free, a rigid body that moves under the load its grains put on it (integrate/velocity_verlet:
// half_kick_shells, drift_shells), as a soft-particle moves in a medium resolved grain by grain;
// a thin spherical shell's moment of inertia, I = 2/3 m Rs^2, when the scene rotates.
//
// Contact radius (our choice, stated in docs/physics.md): Hertz's theory for a convex sphere
// touching a concave one of radius Rs gives 1/R12 = 1/r - 1/Rs, R12 = r Rs / (Rs - r), the
// physically consistent geometry. `ShellContactRadius::particle` uses R12 = r instead (the
// shell treated like a plane wall), for comparison.
#pragma once
#include "core/types.hpp"

namespace softpack {

enum class ShellContactRadius { concave, particle };

struct SphericalShell {
  Vec3 centre;
  double radius = 0.0;  ///< Rs [m]
  int body = kNoBody;   ///< the soft-particle whose grains it confines
  Vec3 velocity = Vec3::Zero();
  Vec3 spin = Vec3::Zero();  ///< angular velocity about the centre while a driver turns it [rad/s]
  int material = 0;
  ShellContactRadius contact_radius = ShellContactRadius::concave;
  double mass = 0.0;  ///< [kg]; 0: kinematic

  bool free() const { return mass > 0.0; }

  /// Velocity of the shell's surface at the point p.
  Vec3 surface_velocity(const Vec3& p) const { return velocity + spin.cross(p - centre); }
  /// Overlap of a sphere (x, r) inside the shell: h = |x - c| + r - Rs (h > 0 in contact).
  double overlap(const Vec3& x, double r) const { return (x - centre).norm() + r - radius; }
};

}  // namespace softpack
