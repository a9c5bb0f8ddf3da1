// The points a law is fitted to, and what the fits of analysis/power_fit.cpp check and choose
// about them before fitting: lengths and finite values, their order, the weights. Internal to
// the fits (analysis/power_fit.hpp is the interface).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "analysis/power_fit.hpp"

namespace softpack::fit {

/// The fitted points; s = σ (stderr weighting), y (relative) or 1 (unweighted).
struct FitPoints {
  std::vector<double> x, y, s;
};

/// InputError: lengths that differ, values that are not finite, negative standard errors.
void check_lengths(std::span<const double> x, std::span<const double> y, std::span<const double> e, const char* yname);
/// InputError: onset_force outside [0, 1), delta_n_max <= 0.
void check_options(const FitOptions& o, const char* law);
/// Indices of x in increasing order.
std::vector<std::size_t> sorted_order(std::span<const double> x);
/// Fills d.s with the weighting's scales; records the choice in `fit` (weighted, weighting, a note).
void choose_weights(FitPoints& d, const std::vector<double>& sigma, bool have_errors, FitOptions::Weighting w, PowerLawFit& fit);
/// "0.1, 0.2"
std::string list_of(const std::vector<double>& v);

}  // namespace softpack::fit
