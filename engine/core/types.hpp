// Basic numeric types shared by the whole engine. Units are SI everywhere.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, rotations
#include <array>
#include <cstdint>
#include <limits>

namespace softpack {

using Vec3 = Eigen::Vector3d;

/// A symmetric 3x3 tensor by its six components: xx, yy, zz, xy, xz, yz.
using SymmetricTensor = std::array<double, 6>;

/// A value that is not known (a missing error, an empty average).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Body id of a sphere that belongs to no soft-particle.
inline constexpr int kNoBody = -1;

}  // namespace softpack
