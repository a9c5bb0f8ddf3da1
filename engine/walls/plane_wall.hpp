// A plane wall: a solid sphere of infinite radius (the paper's soft-solid partner), so the
// reduced radius of Eq. 3 is the particle's radius, R12 = r. It acts on every sphere.
#pragma once
#include "core/types.hpp"

namespace softpack {

struct PlaneWall {
  Vec3 point;   ///< a point of the plane [m]
  Vec3 normal;  ///< unit normal, pointing to the side where the spheres are
  Vec3 velocity = Vec3::Zero();  ///< prescribed translation velocity [m/s]
  int material = 0;

  /// Signed distance from the plane to x, positive on the spheres' side.
  double distance(const Vec3& x) const { return (x - point).dot(normal); }
  /// Overlap h = r - distance (h > 0 in contact).
  double overlap(const Vec3& x, double r) const { return r - distance(x); }
};

}  // namespace softpack
