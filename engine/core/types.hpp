// Basic numeric types shared by the whole engine. Units are SI everywhere.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, rotations
#include <cstdint>
#include <limits>

namespace softpack {

using Vec3 = Eigen::Vector3d;

/// A value that is not known (a missing error, an empty average).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Body id of a sphere that belongs to no soft-particle.
inline constexpr int kNoBody = -1;

}  // namespace softpack
