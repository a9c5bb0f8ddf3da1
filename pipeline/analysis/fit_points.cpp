#include "analysis/fit_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace softpack::fit {

void check_lengths(std::span<const double> x, std::span<const double> y, std::span<const double> e, const char* yname) {
  if (x.size() != y.size())
    throw InputError(fmt::format("delta_n has {} values but {} has {}; allowed: the same number", x.size(), yname, y.size()));
  if (!e.empty() && e.size() != x.size())
    throw InputError(fmt::format("delta_n has {} values but the standard errors have {}; allowed: the same number or none",
                                 x.size(), e.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw InputError(fmt::format("point {} (delta_n = {}, {} = {}) is not finite; allowed: finite numbers", i, x[i], yname, y[i]));
    if (!e.empty() && !(e[i] >= 0.0) )
      throw InputError(fmt::format("point {} (delta_n = {}): standard error {} is not allowed; allowed: finite numbers >= 0", i,
                                   x[i], e[i]));
    if (!e.empty() && !std::isfinite(e[i]))
      throw InputError(fmt::format("point {} (delta_n = {}): standard error {} is not finite", i, x[i], e[i]));
  }
}

std::vector<std::size_t> sorted_order(std::span<const double> x) {
  std::vector<std::size_t> idx(x.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
  return idx;
}

void choose_weights(FitPoints& d, const std::vector<double>& sigma, bool have_errors, FitOptions::Weighting w, PowerLawFit& fit) {
  if (w == FitOptions::Weighting::relative) {
    fit.weighted = true;
    fit.weighting = "relative";
    d.s = d.y;  // every fitted y > 0 (Eq. 7: loaded; Eq. 8: kt > 0)
    fit.notes.push_back("weighted by 1/value^2 (relative deviations)");
    return;
  }
  fit.weighted = have_errors && w == FitOptions::Weighting::standard_error;
  std::string why = w == FitOptions::Weighting::unweighted ? "unweighted (as chosen)"
                    : have_errors                          ? ""
                                                           : "unweighted: no standard errors given";
  if (fit.weighted)
    for (std::size_t i = 0; i < sigma.size(); ++i)
      if (!(sigma[i] > 0.0)) {
        fit.weighted = false;
        why = fmt::format("unweighted: the standard error is {} at delta_n = {}", sigma[i], d.x[i]);
        break;
      }
  d.s = fit.weighted ? sigma : std::vector<double>(d.x.size(), 1.0);
  fit.weighting = fit.weighted ? "stderr" : "unweighted";
  fit.notes.push_back(fit.weighted ? "weighted by 1/stderr^2" : why);
}

void check_options(const FitOptions& o, const char* law) {
  if (!(o.onset_force >= 0.0) || !(o.onset_force < 1.0))
    throw InputError(fmt::format("{}: onset_force = {} is not allowed; allowed: 0 <= onset_force < 1 (a fraction of the largest force)",
                                 law, o.onset_force));
  if (!(o.delta_n_max > 0.0))
    throw InputError(fmt::format("{}: delta_n_max = {} is not allowed; allowed: delta_n_max > 0", law, o.delta_n_max));
}

std::string list_of(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + fmt::format("{}", x);
  return s;
}

}  // namespace softpack::fit
