// Statistics over seeds, written once: the mean of a value measured on several seeds with the
// standard error of that mean (s/√n, s the sample standard deviation, n − 1), and the
// leave-one-seed-out (jackknife) standard error of a quantity computed from all seeds but one.
// The averages (average.hpp), the fits' jackknife (fit_selection.hpp), the verdict's zero-mean
// test (verdict.hpp), the packing study and the studies' reports all compute them here, in one
// order of operations: the mean is Σ (x_i / n) (the order of the archived averages and fits).
#pragma once
#include <Eigen/Core>

#include <vector>

namespace softpack {

/// Mean and standard error of the mean.
struct MeanError {
  double mean = 0.0, error = 0.0;
};

/// What mean_error says where the seeds cannot tell: an error from one value, a mean from none.
enum class FewSeeds {
  /// error 0 for one value, mean and error 0 for none: finite, so that a fit weighted by the
  /// errors takes it (the average files, the zero-mean test, the packing study, the reports).
  zero,
  /// NaN, "not known" (the coarse-grain report, which prints it "–").
  not_known,
};

/// The mean Σ (x_i / n) and the standard error of the mean √(Σ (x_i − mean)² / (n − 1) / n) of
/// `values` (one per seed).
MeanError mean_error(const std::vector<double>& values, FewSeeds few = FewSeeds::zero);

/// The value of rank round(q (n − 1)) among the sorted `values`, 0 for none: the reports'
/// medians (q = 0.5) and 90 % points of a distribution (no interpolation between ranks).
double rank_quantile(std::vector<double> values, double q);

/// The jackknife covariance of four coefficients from their values θ_j computed without seed j,
/// for each seed in turn: Σ (θ_j − θ̄)(θ_j − θ̄)ᵀ · ((n − 1) / n), θ̄ = Σ (θ_j / n); its
/// diagonal's square roots are the coefficients' jackknife standard errors. NaN for fewer than two.
Eigen::Matrix4d jackknife_covariance(const std::vector<Eigen::Vector4d>& leave_one_out);

/// The jackknife standard error of one quantity, as jackknife_covariance's: √(Σ (θ_j − θ̄)² ·
/// ((n − 1) / n)); NaN for fewer than two.
double jackknife_error(const std::vector<double>& leave_one_out);

}  // namespace softpack
