// Statistics of a packing in its shell (centred at the origin): solid fraction, radial
// profile of the solid fraction, the depletion next to the shell, and the size exponent.
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"
#include "packing/power_law.hpp"

namespace softpack {

/// Volume of a sphere (centre at distance d from the origin, radius a) inside the ball of
/// radius R about the origin: full, none, or the lens of two intersecting spheres.
double volume_inside_ball(double d, double a, double R);

struct RadialProfile {
  std::vector<double> r_inner, r_outer;  ///< bin edges [m]
  std::vector<double> solid_fraction;    ///< solid volume in the bin / bin volume
};

/// Solid fraction in `bins` concentric shells of equal thickness from 0 to Rs (exact volumes).
RadialProfile radial_profile(std::span<const Vec3> centres, std::span<const double> radii, double Rs, int bins);

struct PackingStatistics {
  double solid_fraction = 0.0;   ///< rho_i: sum of sphere volumes / shell volume
  double bulk_fraction = 0.0;    ///< solid fraction within Rs - 2 r_max of the centre
  double depletion_length = 0.0; ///< integral of (1 - phi(r)/phi_bulk) dr over the outer 2 r_max [m]
  double min_shell_gap = 0.0;    ///< smallest gap between a sphere and the shell [m]
  power_law::Fit exponent;       ///< maximum-likelihood b of the final radii
  RadialProfile profile;
};

PackingStatistics packing_statistics(std::span<const Vec3> centres, std::span<const double> radii, double Rs,
                                     double r_max, int bins);

}  // namespace softpack
