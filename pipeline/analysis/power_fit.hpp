// Fits of the soft-particle contact laws (paper §5):
//
//   Eq. 7 (normal):      F(Δn)  = a Δn^b + c  for Δn >= δ, 0 below;  δ = (−c/a)^(1/b)
//   Eq. 8 (tangential):  kt(Δn) = a Δn^b + c  for Δn >= δ, 0 below;  c = −a δ^b, δ from Eq. 7
//
// Nonlinear least squares with Eigen's Levenberg–Marquardt (MINPACK, analytic Jacobian).
//
// Weighting (FitOptions::weighting): `stderr`, residuals divided by the standard errors σ_i
// (weights 1/σ_i²) when every fitted point has a finite σ_i > 0, else unweighted; `unweighted`;
// `relative`, residuals divided by the measured value y_i (weights 1/y_i²: every point's relative
// deviation counts alike, as on a log scale, which suits a law spanning decades). The result says
// which was used.
//
// Onset (FitOptions::onset_force): Eq. 7 is fitted to the points whose force is at least
// onset_force × the largest force of the curve, from the last point below it on (a point above it
// before one below contradicts Eq. 7 and is left out, with a note). The default, 1e-9, counts any
// force above round-off; a larger one (1e-2, say) ignores the grazing forces of a few grains that
// the relaxation leaves near the onset, which carry no load (docs/fit.md). delta_n_max bounds the
// fitted range from above (points beyond it are left out, with a note).
//
// Errors: cov = s² (JᵀWJ)⁻¹ with s² = χ²/(n − p) (χ² the weighted sum of squared residuals,
// p the number of free parameters), i.e. the standard errors are scaled by the scatter about
// the fit, weighted or not: the seed-to-seed standard errors set the relative weights, the
// residuals the overall scale (the model is an empirical law, its misfit must show in the
// errors). chi2_per_dof = s² is reported, so the unscaled errors are a_error/sqrt(s²).
// δ's error is first-order propagation with the full covariance of (a, b, c). For Eq. 8 δ is
// treated as exact: c = −a δ^b and its error come from the covariance of (a, b) only.
//
// Start values: the best (lowest χ²) of two starts, each polished by LM:
//   1. a log-log straight line through the points (a, b; c = 0);
//   2. a scan over b (log-spaced 0.2 … 20) with a and c solved by linear least squares.
#pragma once
#include <Eigen/Core>

#include "analysis/fit_options.hpp"
#include "core/types.hpp"
#include <span>
#include <string>
#include <vector>

namespace softpack::fit {

struct PowerLawFit {
  double a = 0.0, a_error = 0.0;
  double b = 0.0, b_error = 0.0;
  double c = 0.0, c_error = 0.0;
  double delta = 0.0, delta_error = 0.0;  ///< Eq. 7: fitted; Eq. 8: the δ used (exact)
  std::size_t points = 0;                 ///< points fitted
  bool weighted = false;                  ///< weights used (1/σ² or 1/y²), else unweighted
  std::string weighting = "unweighted";   ///< what was used: stderr, relative or unweighted
  double onset_force = 0.0;               ///< Eq. 7: the force [N] a loaded point exceeds
  double chi2_per_dof = 0.0;              ///< s² = χ²/(n − p)
  double dn_min = 0.0, dn_max = 0.0;      ///< range of Δn fitted
  Eigen::MatrixXd covariance;             ///< of (a, b, c) for Eq. 7, of (a, b) for Eq. 8
  std::vector<std::string> notes;         ///< weighting, excluded points, δ = 0, …
};

/// Minimum numbers of points: one more than the free parameters.
inline constexpr std::size_t kNormalMinPoints = 4;
inline constexpr std::size_t kTangentialMinPoints = 3;
/// Eq. 7 on the loaded points: the run of points with F > onset (FitOptions) and Δn > 0 after
/// the last point below it, up to delta_n_max (in increasing Δn; an isolated loaded point before
/// an unloaded one contradicts Eq. 7 and is left out, with a note). `error` may be empty
/// (unweighted unless the weighting is relative).
/// Throws InputError: mismatched lengths, non-finite values, fewer than 4 points (the message
/// gives the count and the Δn where the force starts), a fit that does not converge, or a ≤ 0.
PowerLawFit fit_normal_law(std::span<const double> delta_n, std::span<const double> force,
                           std::span<const double> error, const FitOptions& options = {});

/// Eq. 8 with c = −a δ^b on the points with Δn >= δ and kt > 0 (two free parameters a, b).
/// Throws InputError as fit_normal_law, for fewer than 3 points, or δ < 0 / non-finite.
/// The options' weighting and delta_n_max apply (onset_force does not: δ comes from Eq. 7).
PowerLawFit fit_tangential_law(std::span<const double> delta_n, std::span<const double> kt,
                               std::span<const double> error, double delta, const FitOptions& options = {});

/// Eq. 7/8 evaluated: a Δn^b + c for Δn >= δ, else 0 (δ as in the fit).
double evaluate(const PowerLawFit& fit, double delta_n);

/// How well an Eq. 7 fit describes a curve, every form judged alike (experiments/criteria.yaml,
/// fit.judge): χ² over every point with Δn <= delta_n_max of max(0, law), each residual over
/// σ_i = max(stderr_i, sigma_floor × the curve's largest |F|), dof = points − 3; and the
/// Wald-Wolfowitz runs test of the residuals' signs where the law or the force is loaded
/// (z = (runs − μ)/σ; NaN when every residual has one sign: then no test, and the fit is not
/// adequate).
struct Judgement {
  double chi2_per_dof = kNaN;
  std::size_t points = 0;         ///< points judged
  std::size_t signed_points = 0;  ///< points in the runs test
  std::size_t runs = 0;
  double runs_z = kNaN;
};
Judgement judge_normal_law(const PowerLawFit& fit, std::span<const double> delta_n, std::span<const double> force,
                           std::span<const double> error, double sigma_floor, double delta_n_max);

}  // namespace softpack::fit
