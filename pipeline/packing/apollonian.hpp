// A two-dimensional Apollonian gasket, the packing of Figure 1 of the paper: the hierarchy of
// ever smaller circles that fills the voids between larger ones, the 2D picture of the
// space-filling packings that soft-particles stand in for.
//
// Start: the integral gasket with curvatures (-1, 2, 2, 3): the bounding circle of radius 1 at
// the origin, two circles of radius 1/2 at (-1/2, 0) and (1/2, 0), and the circle of radius 1/3
// at (0, 2/3), found from the other three by the complex Descartes theorem. Chosen because every
// curvature k and every "curvature-centre" k z is then an (Gaussian) integer, so the whole
// construction is exact in double precision (up to |k| = 2^53): tangency holds to rounding of
// the final division z = (k z) / k, and the curvatures can be checked against the known sequence.
//
// Generations: 0 = the three inner circles of the start; generation g >= 1 fills the 4 * 3^(g-1)
// curvilinear triangles (gaps) left by generation g - 1, one circle per gap. The bounding circle
// is returned first, with generation -1 (it contains the packing, it is not part of it).
#pragma once
#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace softpack {

/// A circle by signed curvature k (negative: the bounding circle, which contains the others)
/// and curvature-centre w = k z, the variables in which the Descartes theorem is linear.
struct DescartesCircle {
  double k = 0.0;
  std::complex<double> w;
};

/// Both circles tangent to three mutually tangent ones (Descartes: k4 = k1 + k2 + k3
/// +- 2 sqrt(k1 k2 + k2 k3 + k3 k1); complex Descartes: w4 = w1 + w2 + w3
/// +- 2 sqrt(w1 w2 + w2 w3 + w3 w1)). The two signs of the centre are paired with those of
/// the curvature by tangency, since the complex root's sign is arbitrary. Used for the start;
/// the recursion uses the exact reflection w' = 2 (w1 + w2 + w3) - w4 instead.
std::array<DescartesCircle, 2> descartes_solutions(const DescartesCircle& a, const DescartesCircle& b,
                                                   const DescartesCircle& c);

struct ApollonianOptions {
  std::optional<int> depth;          ///< last generation generated; none: only min_radius stops
  std::optional<double> min_radius;  ///< circles smaller than this are not generated (nor their gaps)
};

/// Largest depth accepted without min_radius: depth 12 gives 1.06 million circles.
inline constexpr int kMaxDepthWithoutMinRadius = 12;
/// Smallest min_radius accepted: 1.36 million circles (the count grows as min_radius^-1.3057;
/// 1e-6 gives 27 million).
inline constexpr double kSmallestMinRadius = 1e-5;

/// Throws InputError naming --depth or --min-radius and the allowed range.
void validate(const ApollonianOptions& options);

struct ApollonianCircle {
  double x = 0.0, y = 0.0, r = 0.0;
  double k = 0.0;      ///< signed curvature: -1 for the bounding circle, 1/r otherwise
  int generation = 0;  ///< -1 for the bounding circle
  /// Indices (in the returned vector) of the three circles it was built from; -1 in generation <= 0.
  std::array<std::int32_t, 3> parents{-1, -1, -1};
};

/// The cumulative size distribution N(radius > r) ~ r^(-d_f), fitted by least squares of
/// log N against log r at 10 log-spaced radii per decade in [r_lo, r_hi].
struct SizeExponentFit {
  double d_f = 0.0;  ///< NaN when the range is shorter than a decade
  double r_lo = 0.0, r_hi = 0.0;
  int points = 0;
};

/// The known fractal dimension of the Apollonian gasket (McMullen 1998: 1.305688...).
inline constexpr double kApollonianDimension = 1.305688;
/// Upper end of the fit. N(radius > r) r^1.3057 is flat to 0.5% below r = 0.005 but 8% higher
/// at r = 0.05, where only the 22 largest circles count: their discreteness biases the slope
/// low (1.298 instead of 1.306 over [1e-4, 0.05]). Above r = 0.02 there are fewer than 70.
inline constexpr double kFitLargestRadius = 0.02;

SizeExponentFit fit_size_exponent(const std::vector<ApollonianCircle>& circles, double r_lo, double r_hi);

struct ApollonianPacking {
  /// The bounding circle, then the packing sorted by radius descending, then x, then y.
  std::vector<ApollonianCircle> circles;
  std::vector<std::size_t> per_generation;  ///< circle count of generation 0, 1, ...
  /// Every circle of the full gasket with a radius above this one is in `circles` (the largest
  /// circle of an unfilled gap); the size distribution is complete above it.
  double complete_above = 0.0;
  /// fit_size_exponent over [complete_above, kFitLargestRadius].
  SizeExponentFit fit;
};

/// Validates, then fills every gap down to options.depth and/or options.min_radius. Deterministic.
ApollonianPacking apollonian_gasket(const ApollonianOptions& options);

}  // namespace softpack
