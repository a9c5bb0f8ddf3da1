// Hertz normal contact law, paper Eq. 3:
//
//   Fn = sqrt(R12) h^(3/2) / D,   R12 = R1 R2 / (R1 + R2),   D from Eq. 4 (core/material.hpp)
//
// Inputs: reduced radius R12 [m], overlap h [m] (h > 0 in contact), D [1/Pa].
// We precompute the per-contact stiffness kn = sqrt(R12) / D [N/m^(3/2)] once per contact
// so that the inner loop evaluates Fn = kn h^(3/2) with one square root.
#pragma once
#include <cmath>

namespace softpack::hertz {

/// R12 = R1 R2 / (R1 + R2); a plane wall is a sphere of infinite radius, R12 = R1.
[[gnu::always_inline]] inline double reduced_radius(double R1, double R2) { return R1 * R2 / (R1 + R2); }

/// R12 of a sphere of radius r touching the inside of a concave spherical shell of radius Rs:
/// the shell's curvature is negative, 1/R12 = 1/r - 1/Rs, so R12 = r Rs / (Rs - r).
[[gnu::always_inline]] inline double reduced_radius_concave(double r, double Rs) { return r * Rs / (Rs - r); }

/// kn = sqrt(R12) / D so that Fn = kn h^(3/2).
[[gnu::always_inline]] inline double stiffness(double R12, double D) { return std::sqrt(R12) / D; }

/// Eq. 3: Fn = kn h^(3/2) [N], h > 0.
[[gnu::always_inline]] inline double force(double kn, double h) { return kn * h * std::sqrt(h); }

/// Elastic energy stored in the contact: integral of Fn dh = 2/5 kn h^(5/2) [J].
[[gnu::always_inline]] inline double energy(double kn, double h) { return 0.4 * kn * h * h * std::sqrt(h); }

}  // namespace softpack::hertz
