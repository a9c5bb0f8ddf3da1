// Basic numeric types shared by the whole engine. Units are SI everywhere.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, rotations
#include <cstdint>

namespace softpack {

using Vec3 = Eigen::Vector3d;

/// Body id of a sphere that belongs to no soft-particle.
inline constexpr int kNoBody = -1;

}  // namespace softpack
