#include "analysis/power_fit.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unsupported/Eigen/NonLinearOptimization>

#include "analysis/fit_points.hpp"
#include "analysis/fit_solver.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace softpack::fit {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

using Data = FitPoints;
using namespace solver;

/// Eq. 7: a x^b + c, parameters (a, b, c).
struct NormalModel {
  static constexpr int kParams = 3;
  double value(double x, const VectorXd& p) const { return p[0] * std::pow(x, p[1]) + p[2]; }
  void gradient(double x, const VectorXd& p, double* g) const {
    const double xb = std::pow(x, p[1]);
    g[0] = xb;
    g[1] = p[0] * xb * std::log(x);
    g[2] = 1.0;
  }
};

/// Eq. 7 clamped (FitOptions::Form::clamped): max(0, a x^b + c), parameters (a, b, c); zero
/// below δ, where it does not depend on the parameters.
struct ClampedModel {
  static constexpr int kParams = 3;
  double value(double x, const VectorXd& p) const {
    const double xb = x > 0.0 ? std::pow(x, p[1]) : 0.0;
    return std::max(0.0, p[0] * xb + p[2]);
  }
  void gradient(double x, const VectorXd& p, double* g) const {
    const double xb = x > 0.0 ? std::pow(x, p[1]) : 0.0;
    if (!(p[0] * xb + p[2] > 0.0)) {
      g[0] = g[1] = g[2] = 0.0;
      return;
    }
    g[0] = xb;
    g[1] = x > 0.0 ? p[0] * xb * std::log(x) : 0.0;
    g[2] = 1.0;
  }
};

/// Eq. 8 with c = −a δ^b: a (x^b − δ^b), parameters (a, b); δ fixed.
struct TangentialModel {
  static constexpr int kParams = 2;
  double delta = 0.0;
  double value(double x, const VectorXd& p) const { return p[0] * (std::pow(x, p[1]) - std::pow(delta, p[1])); }
  void gradient(double x, const VectorXd& p, double* g) const {
    const double xb = std::pow(x, p[1]);
    const double db = std::pow(delta, p[1]);
    g[0] = xb - db;
    g[1] = p[0] * (xb * std::log(x) - (delta > 0.0 ? db * std::log(delta) : 0.0));
  }
};

// δ = (−c/a)^(1/b) and its first-order error from the covariance of (a, b, c); δ = 0 when c >= 0.
void set_delta(PowerLawFit& fit) {
  if (fit.c < 0.0) {
    fit.delta = std::pow(-fit.c / fit.a, 1.0 / fit.b);
    const Eigen::Vector3d g{-fit.delta / (fit.a * fit.b), -fit.delta * std::log(fit.delta) / fit.b,
                            fit.delta / (fit.b * fit.c)};
    fit.delta_error = std::sqrt(std::max(0.0, g.dot(fit.covariance * g)));
  } else {
    fit.delta = 0.0;
    fit.delta_error = kNaN;
    fit.notes.push_back(fmt::format("c = {:.4g} >= 0: the fitted law is positive for every delta_n > 0, so delta = 0 "
                                    "(its error is undefined)",
                                    fit.c));
  }
}

// The solution of an Eq. 7 fit into `fit`: a > 0 and b > 0 checked, the coefficients, the points,
// χ²/dof, the covariance and the standard errors (δ is set_delta's).
template <class Model>
void take_normal_solution(PowerLawFit& fit, const Data& d, const Model& model, const Solution& best, const char* law) {
  const VectorXd& p = best.p;
  if (!(p[0] > 0.0) || !(p[1] > 0.0))
    throw InputError(fmt::format("{}: fitted a = {:.6g}, b = {:.6g}; allowed: a > 0 and b > 0 (a force growing with delta_n)",
                                 law, p[0], p[1]));
  const std::size_t n = d.x.size();
  fit.a = p[0], fit.b = p[1], fit.c = p[2];
  fit.points = n;
  fit.dn_min = d.x.front(), fit.dn_max = d.x.back();
  fit.chi2_per_dof = best.chi2 / static_cast<double>(n - 3);
  fit.covariance = covariance(d, model, p, fit.chi2_per_dof, law);
  fit.a_error = std::sqrt(fit.covariance(0, 0));
  fit.b_error = std::sqrt(fit.covariance(1, 1));
  fit.c_error = std::sqrt(fit.covariance(2, 2));
}

// The largest |F| of the points with Δn <= delta_n_max.
double largest_force(std::span<const double> delta_n, std::span<const double> force, double delta_n_max) {
  double largest = 0.0;
  for (std::size_t i = 0; i < force.size(); ++i)
    if (delta_n[i] <= delta_n_max) largest = std::max(largest, std::abs(force[i]));
  return largest;
}

// Eq. 7 clamped to zero below δ, fitted to every point up to delta_n_max, δ free: started from
// the loaded fits (stderr and unweighted weights, onset 1e-3) and polished on the clamped model.
PowerLawFit fit_clamped_normal_law(std::span<const double> delta_n, std::span<const double> force,
                                   std::span<const double> error, const FitOptions& options) {
  constexpr const char* law = "Eq. 7 fit of the normal force (clamped)";
  const std::vector<std::size_t> order = sorted_order(delta_n);
  const double floor = options.sigma_floor * largest_force(delta_n, force, options.delta_n_max);
  PowerLawFit fit;
  Data d;
  for (std::size_t i : order) {
    if (delta_n[i] > options.delta_n_max) continue;
    d.x.push_back(delta_n[i]);
    d.y.push_back(force[i]);
    const bool weighted = options.weighting == FitOptions::Weighting::standard_error && !error.empty();
    d.s.push_back(weighted ? std::max(error[i], floor) : 1.0);
  }
  if (!(floor > 0.0)) throw InputError(fmt::format("{}: the force is zero at every point", law));
  fit.weighted = options.weighting == FitOptions::Weighting::standard_error && !error.empty();
  fit.weighting = fit.weighted ? "stderr" : "unweighted";
  fit.notes.push_back(fmt::format("clamped: max(0, a dn^b + c) fitted to every point with delta_n <= {:g}{}", options.delta_n_max,
                                  fit.weighted ? fmt::format(", weighted by 1/stderr^2 with stderr >= {:.3g} N ({:g} of the "
                                                             "largest force)",
                                                             floor, options.sigma_floor)
                                               : ", unweighted"));
  const std::size_t n = d.x.size();
  if (n < kNormalMinPoints)
    throw InputError(fmt::format("{}: {} points; allowed: at least {}", law, n, kNormalMinPoints));
  const ClampedModel model;
  Solution best;
  for (const auto w : {FitOptions::Weighting::standard_error, FitOptions::Weighting::unweighted}) {
    FitOptions start = options;
    start.form = FitOptions::Form::loaded;
    start.weighting = w;
    start.onset_force = 1e-3;
    try {
      const PowerLawFit s = fit_normal_law(delta_n, force, error, start);
      const Solution t = levenberg_marquardt(d, model, VectorXd{{s.a, s.b, s.c}});
      if (t.chi2 < best.chi2) best = t;
    } catch (const InputError&) {
      // that start does not exist; the other may
    }
  }
  if (!std::isfinite(best.chi2))
    throw InputError(fmt::format("{}: no start: the loaded fits failed on these points", law));
  if (best.status == static_cast<int>(Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation))
    fit.notes.push_back("Levenberg-Marquardt stopped at its evaluation limit");
  fit.onset_force = 0.0;
  take_normal_solution(fit, d, model, best, law);
  set_delta(fit);
  return fit;
}

}  // namespace

PowerLawFit fit_normal_law(std::span<const double> delta_n, std::span<const double> force, std::span<const double> error,
                           const FitOptions& options) {
  constexpr const char* law = "Eq. 7 fit of the normal force";
  check_lengths(delta_n, force, error, "Fn");
  check_options(options, law);
  if (options.form == FitOptions::Form::clamped) return fit_clamped_normal_law(delta_n, force, error, options);
  const std::vector<std::size_t> order = sorted_order(delta_n);
  // The run of loaded points after the last unloaded one, within delta_n_max. A force within
  // round-off of zero (a net force of ~1e-19 N left by summing grain forces) is never loaded;
  // a larger onset_force also leaves out the grazing forces of a few grains near the onset.
  const double largest = largest_force(delta_n, force, options.delta_n_max);
  const double zero = options.onset_force * largest;
  std::size_t first = 0, end = order.size();
  while (end > 0 && delta_n[order[end - 1]] > options.delta_n_max) --end;
  for (std::size_t k = 0; k < end; ++k)
    if (!(force[order[k]] > zero) || !(delta_n[order[k]] > 0.0)) first = k + 1;
  std::vector<double> isolated;
  for (std::size_t k = 0; k < first; ++k)
    if (force[order[k]] > zero) isolated.push_back(delta_n[order[k]]);

  PowerLawFit fit;
  fit.onset_force = zero;
  if (end < order.size())
    fit.notes.push_back(fmt::format("left out: delta_n above delta_n_max = {} ({} point{})", options.delta_n_max,
                                    order.size() - end, order.size() - end == 1 ? "" : "s"));
  if (options.onset_force != kZeroForceRelative)
    fit.notes.push_back(fmt::format("loaded: Fn > {:.3g} N ({:g} of the largest force)", zero, options.onset_force));
  Data d;
  std::vector<double> sigma;
  for (std::size_t k = first; k < end; ++k) {
    d.x.push_back(delta_n[order[k]]);
    d.y.push_back(force[order[k]]);
    if (!error.empty()) sigma.push_back(error[order[k]]);
  }
  const std::size_t n = d.x.size();
  if (n < kNormalMinPoints) {
    const std::string where =
        n == 0 ? std::string("the force is never positive after its last zero")
               : fmt::format("the force starts at delta_n = {}", d.x.front());
    throw InputError(fmt::format("{}: {} point{} with Fn > 0 ({}{}); allowed: at least {} (a, b, c and one degree of freedom)", law,
                                 n, n == 1 ? "" : "s", where,
                                 isolated.empty() ? "" : fmt::format("; isolated positive points before a zero at delta_n = {}",
                                                                     list_of(isolated)),
                                 kNormalMinPoints));
  }
  if (!isolated.empty())
    fit.notes.push_back(fmt::format("left out: positive force before a zero at delta_n = {} (Eq. 7: F = 0 below delta)",
                                    list_of(isolated)));
  choose_weights(d, sigma, !error.empty(), options.weighting, fit);

  const NormalModel model;
  // Start 1: log-log line, c = 0.
  const auto [a0, b0] = log_log_start(d);
  // Start 2: the scan over b with (a, c) by linear least squares.
  double scan_chi2 = std::numeric_limits<double>::infinity();
  VectorXd scan_start(3);
  for (double b : exponent_grid()) {
    double sw = 0, sg = 0, sgg = 0, sy = 0, sgy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 1.0 / (d.s[i] * d.s[i]), g = std::pow(d.x[i], b);
      sw += w, sg += w * g, sgg += w * g * g, sy += w * d.y[i], sgy += w * g * d.y[i];
    }
    const double det = sgg * sw - sg * sg;
    if (!(std::abs(det) > 0.0)) continue;
    const VectorXd p{{(sgy * sw - sg * sy) / det, b, (sgg * sy - sg * sgy) / det}};
    if (!(p[0] > 0.0)) continue;
    const double c2 = chi2(d, model, p);
    if (c2 < scan_chi2) scan_chi2 = c2, scan_start = p;
  }
  const Solution best = best_of_two_starts(d, model, VectorXd{{a0, b0, 0.0}}, scan_chi2, scan_start, law, fit);

  take_normal_solution(fit, d, model, best, law);
  set_delta(fit);
  if (fit.c < 0.0) {
    const double last_zero = first > 0 ? delta_n[order[first - 1]] : 0.0;
    if (fit.delta < last_zero || fit.delta > fit.dn_min)
      fit.notes.push_back(fmt::format("delta = {:.4g} lies outside [{}, {}], between the last zero force and the first positive one",
                                      fit.delta, last_zero, fit.dn_min));
  }
  return fit;
}

PowerLawFit fit_tangential_law(std::span<const double> delta_n, std::span<const double> kt, std::span<const double> error,
                               double delta, const FitOptions& options) {
  constexpr const char* law = "Eq. 8 fit of the tangential spring constant";
  check_lengths(delta_n, kt, error, "kt");
  check_options(options, law);
  if (!(delta >= 0.0) || !std::isfinite(delta))
    throw InputError(fmt::format("{}: delta = {} is not allowed; allowed: a finite delta >= 0 (from the normal fit)", law, delta));
  const std::vector<std::size_t> order = sorted_order(delta_n);
  PowerLawFit fit;
  Data d;
  std::vector<double> sigma, dropped;
  std::size_t beyond = 0;
  for (std::size_t i : order) {
    if (!(delta_n[i] >= delta) || !(delta_n[i] > 0.0)) continue;
    if (delta_n[i] > options.delta_n_max) {
      ++beyond;
      continue;
    }
    if (!(kt[i] > 0.0)) {
      dropped.push_back(delta_n[i]);
      continue;
    }
    // Δn = δ exactly: the model is 0 there, a positive kt is consistent with no (a, b).
    if (delta_n[i] == delta) {
      dropped.push_back(delta_n[i]);
      continue;
    }
    d.x.push_back(delta_n[i]);
    d.y.push_back(kt[i]);
    if (!error.empty()) sigma.push_back(error[i]);
  }
  const std::size_t n = d.x.size();
  if (n < kTangentialMinPoints)
    throw InputError(fmt::format("{}: {} point{} with delta_n > delta = {:.4g} and kt > 0{}; allowed: at least {} (a, b and one "
                                 "degree of freedom)",
                                 law, n, n == 1 ? "" : "s", delta, n == 0 ? "" : fmt::format(" (at delta_n = {})", list_of(d.x)),
                                 kTangentialMinPoints));
  if (!dropped.empty())
    fit.notes.push_back(fmt::format("left out: kt <= 0 (or delta_n = delta) at delta_n = {}", list_of(dropped)));
  if (beyond > 0)
    fit.notes.push_back(fmt::format("left out: delta_n above delta_n_max = {} ({} point{})", options.delta_n_max, beyond,
                                    beyond == 1 ? "" : "s"));
  choose_weights(d, sigma, !error.empty(), options.weighting, fit);

  TangentialModel model;
  model.delta = delta;
  const auto [a0, b0] = log_log_start(d);
  double scan_chi2 = std::numeric_limits<double>::infinity();
  VectorXd scan_start(2);
  for (double b : exponent_grid()) {
    double sgg = 0, sgy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 1.0 / (d.s[i] * d.s[i]), g = std::pow(d.x[i], b) - std::pow(delta, b);
      sgg += w * g * g, sgy += w * g * d.y[i];
    }
    if (!(sgg > 0.0)) continue;
    const VectorXd p{{sgy / sgg, b}};
    if (!(p[0] > 0.0)) continue;
    const double c2 = chi2(d, model, p);
    if (c2 < scan_chi2) scan_chi2 = c2, scan_start = p;
  }
  const Solution best = best_of_two_starts(d, model, VectorXd{{a0, b0}}, scan_chi2, scan_start, law, fit);
  const VectorXd& p = best.p;
  if (!(p[0] > 0.0) || !(p[1] > 0.0))
    throw InputError(fmt::format("{}: fitted a = {:.6g}, b = {:.6g}; allowed: a > 0 and b > 0 (kt growing with delta_n)", law,
                                 p[0], p[1]));
  fit.a = p[0], fit.b = p[1];
  fit.points = n;
  fit.dn_min = d.x.front(), fit.dn_max = d.x.back();
  fit.chi2_per_dof = best.chi2 / static_cast<double>(n - 2);
  fit.covariance = covariance(d, model, p, fit.chi2_per_dof, law);
  fit.a_error = std::sqrt(fit.covariance(0, 0));
  fit.b_error = std::sqrt(fit.covariance(1, 1));
  fit.delta = delta;
  fit.delta_error = 0.0;
  if (delta > 0.0) {
    const double db = std::pow(delta, fit.b);
    fit.c = -fit.a * db;
    const Eigen::Vector2d g{-db, -fit.a * db * std::log(delta)};
    fit.c_error = std::sqrt(std::max(0.0, g.dot(fit.covariance * g)));
  } else {
    fit.c = 0.0;
    fit.c_error = 0.0;
  }
  fit.notes.push_back("c = -a delta^b with delta from the normal fit treated as exact: c_error propagates the covariance of "
                      "(a, b) only");
  return fit;
}

double evaluate(const PowerLawFit& fit, double delta_n) {
  if (delta_n < fit.delta || !(delta_n > 0.0)) return 0.0;
  return fit.a * std::pow(delta_n, fit.b) + fit.c;
}

Judgement judge_normal_law(const PowerLawFit& fit, std::span<const double> delta_n, std::span<const double> force,
                           std::span<const double> error, double sigma_floor, double delta_n_max) {
  check_lengths(delta_n, force, error, "Fn");
  const double floor = sigma_floor * largest_force(delta_n, force, delta_n_max);
  Judgement j;
  double sum = 0.0;
  std::vector<int> signs;
  for (std::size_t i : sorted_order(delta_n)) {
    if (delta_n[i] > delta_n_max) continue;
    const double model = std::max(0.0, evaluate(fit, delta_n[i]));
    const double sigma = std::max(error.empty() ? 0.0 : error[i], floor);
    const double r = (force[i] - model) / sigma;
    sum += r * r;
    ++j.points;
    // Signs where the law or the measurement is loaded (not the exact zeros before the onset).
    if ((model > 0.0 || std::abs(force[i]) > floor) && r != 0.0) signs.push_back(r > 0.0 ? 1 : -1);
  }
  j.chi2_per_dof = j.points > 3 && floor > 0.0 ? sum / static_cast<double>(j.points - 3) : kNaN;
  // Wald-Wolfowitz runs test on the signs of the residuals.
  double np = 0, nm = 0;
  for (int s : signs) (s > 0 ? np : nm) += 1.0;
  j.signed_points = signs.size();
  j.runs = signs.empty() ? 0 : 1;
  for (std::size_t k = 1; k < signs.size(); ++k) j.runs += signs[k] != signs[k - 1] ? 1 : 0;
  const double N = np + nm;
  if (np > 0 && nm > 0 && N > 2) {
    const double mu = 2.0 * np * nm / N + 1.0;
    const double var = (mu - 1.0) * (mu - 2.0) / (N - 1.0);
    j.runs_z = var > 0.0 ? (static_cast<double>(j.runs) - mu) / std::sqrt(var) : kNaN;
  }
  return j;
}

}  // namespace softpack::fit
