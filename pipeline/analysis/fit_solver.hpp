// The nonlinear least squares of the fits (analysis/power_fit.cpp): weighted residuals of a
// model and their Jacobian in the form Eigen's Levenberg–Marquardt expects, χ², the solver from a
// start, the better of two starts, the start values (a log-log line, a scan over the exponent) and
// the covariance at the solution. Internal to the fits (analysis/power_fit.hpp is the interface);
// a model is a type with kParams, value(x, p) and gradient(x, p, g).
#pragma once
#include <fmt/format.h>

#include <Eigen/Core>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/NonLinearOptimization>
#include <utility>
#include <vector>

#include "analysis/fit_points.hpp"
#include "analysis/power_fit.hpp"
#include "core/error.hpp"

namespace softpack::fit::solver {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using Data = FitPoints;

/// Weighted residuals (model − y)/s and their Jacobian, in the form Eigen's LM expects.
template <class Model>
struct Residuals {
  using Scalar = double;
  const Data& data;
  const Model& model;
  int values() const { return static_cast<int>(data.x.size()); }
  int inputs() const { return Model::kParams; }
  int operator()(const VectorXd& p, VectorXd& r) const {
    for (std::size_t i = 0; i < data.x.size(); ++i)
      r[static_cast<Eigen::Index>(i)] = (model.value(data.x[i], p) - data.y[i]) / data.s[i];
    return 0;
  }
  int df(const VectorXd& p, MatrixXd& J) const {
    double g[Model::kParams];
    for (std::size_t i = 0; i < data.x.size(); ++i) {
      model.gradient(data.x[i], p, g);
      for (int k = 0; k < Model::kParams; ++k) J(static_cast<Eigen::Index>(i), k) = g[k] / data.s[i];
    }
    return 0;
  }
};

template <class Model>
double chi2(const Data& data, const Model& model, const VectorXd& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < data.x.size(); ++i) {
    const double r = (model.value(data.x[i], p) - data.y[i]) / data.s[i];
    sum += r * r;
  }
  return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
}

struct Solution {
  VectorXd p;
  double chi2 = std::numeric_limits<double>::infinity();
  int status = 0;
};

/// LM from `start`; a start with a non-finite χ² or a non-finite result gives χ² = inf.
template <class Model>
Solution levenberg_marquardt(const Data& data, const Model& model, const VectorXd& start) {
  Solution sol;
  sol.p = start;
  if (!std::isfinite(chi2(data, model, start))) return sol;
  Residuals<Model> functor{data, model};
  Eigen::LevenbergMarquardt<Residuals<Model>> lm(functor);
  lm.parameters.ftol = 1e-14;
  lm.parameters.xtol = 1e-14;
  lm.parameters.maxfev = 4000;
  sol.status = static_cast<int>(lm.minimize(sol.p));
  bool finite = true;
  for (Eigen::Index k = 0; k < sol.p.size(); ++k) finite = finite && std::isfinite(sol.p[k]);
  if (finite) sol.chi2 = chi2(data, model, sol.p);
  return sol;
}

/// Log-spaced exponents for the scan start.
inline std::vector<double> exponent_grid() {
  std::vector<double> b;
  const int n = 400;
  for (int k = 0; k < n; ++k) b.push_back(0.2 * std::pow(100.0, static_cast<double>(k) / (n - 1)));
  return b;
}

/// Straight line ln y = ln a + b ln x through the points (weights y²/σ², the variance of ln y).
inline std::pair<double, double> log_log_start(const Data& d) {
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    const double w = (d.y[i] / d.s[i]) * (d.y[i] / d.s[i]);
    const double lx = std::log(d.x[i]), ly = std::log(d.y[i]);
    sw += w, sx += w * lx, sy += w * ly, sxx += w * lx * lx, sxy += w * lx * ly;
  }
  const double det = sw * sxx - sx * sx;
  if (!(std::abs(det) > 0.0)) return {std::exp(sy / sw), 1.0};
  const double b = (sw * sxy - sx * sy) / det;
  const double ln_a = (sy - b * sx) / sw;
  return {std::exp(ln_a), b};
}

/// s² (JᵀWJ)⁻¹ at the solution, via the SVD of the column-scaled weighted Jacobian.
// The better of Levenberg-Marquardt from the log-log start and from the scan's best point (when
// the scan found one); InputError when neither converged; a note when it hit its limit.
template <class Model>
Solution best_of_two_starts(const Data& d, const Model& model, const VectorXd& log_log, double scan_chi2,
                            const VectorXd& scan_start, const char* law, PowerLawFit& fit) {
  Solution best = levenberg_marquardt(d, model, log_log);
  if (std::isfinite(scan_chi2)) {
    const Solution s = levenberg_marquardt(d, model, scan_start);
    if (s.chi2 < best.chi2) best = s;
  }
  if (!std::isfinite(best.chi2))
    throw InputError(fmt::format("{}: Levenberg-Marquardt did not converge on the {} points (delta_n {} to {})", law,
                                 d.x.size(), d.x.front(), d.x.back()));
  if (best.status == static_cast<int>(Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation))
    fit.notes.push_back("Levenberg-Marquardt stopped at its evaluation limit");
  return best;
}

template <class Model>
MatrixXd covariance(const Data& data, const Model& model, const VectorXd& p, double s2, const char* law) {
  Residuals<Model> functor{data, model};
  MatrixXd J(static_cast<Eigen::Index>(data.x.size()), Model::kParams);
  functor.df(p, J);
  VectorXd scale = J.colwise().norm().transpose();
  for (Eigen::Index k = 0; k < scale.size(); ++k)
    if (!(scale[k] > 0.0) || !std::isfinite(scale[k]))
      throw InputError(fmt::format("{}: the fit is degenerate (a parameter has no effect on the model)", law));
  const MatrixXd Js = J * scale.cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<MatrixXd> svd(Js, Eigen::ComputeThinV);
  const VectorXd sv = svd.singularValues();
  if (!(sv[sv.size() - 1] > 1e-12 * sv[0]))
    throw InputError(fmt::format("{}: the fit is degenerate (its parameters are not determined by the points)", law));
  const MatrixXd inner = svd.matrixV() * sv.array().square().inverse().matrix().asDiagonal() * svd.matrixV().transpose();
  return s2 * scale.cwiseInverse().asDiagonal() * inner * scale.cwiseInverse().asDiagonal();
}


}  // namespace softpack::fit::solver
