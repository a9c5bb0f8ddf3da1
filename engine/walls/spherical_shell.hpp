// The soft-particle's shell: an invisible, rigid, impenetrable spherical wall of radius Rs,
// of the same material as its grains, that confines the spheres of its own body from inside
// and ignores every other sphere (paper §4).
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

  /// Velocity of the shell's surface at the point p.
  Vec3 surface_velocity(const Vec3& p) const { return velocity + spin.cross(p - centre); }
  /// Overlap of a sphere (x, r) inside the shell: h = |x - c| + r - Rs (h > 0 in contact).
  double overlap(const Vec3& x, double r) const { return (x - centre).norm() + r - radius; }
};

}  // namespace softpack
