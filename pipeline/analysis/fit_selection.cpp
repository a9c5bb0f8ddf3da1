#include "analysis/fit_selection.hpp"

#include <fmt/format.h>

#include <cmath>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"

namespace softpack::fit {
namespace {

double positive_fraction(const ConfigNode& n, double upper) {
  const double v = n.number();
  if (!(v > 0.0 && v <= upper)) n.fail(fmt::format("{} is not allowed; allowed: 0 < value <= {:g}", v, upper));
  return v;
}

// Means and standard errors of the rows over every seed but `leave`.
void leave_one_out(const std::vector<std::vector<double>>& per_seed, std::size_t leave, std::vector<double>& mean,
                   std::vector<double>& error) {
  mean.clear(), error.clear();
  for (const auto& row : per_seed) {
    std::vector<double> rest;
    for (std::size_t s = 0; s < row.size(); ++s)
      if (s != leave) rest.push_back(row[s]);
    const MeanError m = mean_error(rest);
    mean.push_back(m.mean), error.push_back(m.error);
  }
}

Jackknife jackknife(const FitOptions& options, const SceneCurves& curves) {
  Jackknife j;
  if (curves.Fn_per_seed.empty() || curves.Fn_per_seed.size() != curves.delta_n.size()) {
    j.reason = "no per-seed values in the average file (files from before 0.6.0)";
    return j;
  }
  const std::size_t n = curves.Fn_per_seed.front().size();
  if (n < 3) {
    j.reason = fmt::format("{} seeds; a jackknife needs at least 3", n);
    return j;
  }
  std::vector<Eigen::Vector4d> theta;
  for (std::size_t leave = 0; leave < n; ++leave) {
    std::vector<double> mean, error;
    leave_one_out(curves.Fn_per_seed, leave, mean, error);
    try {
      const PowerLawFit f = fit_normal_law(curves.delta_n, mean, error, options);
      theta.push_back(Eigen::Vector4d{f.a, f.b, f.c, f.delta});
    } catch (const InputError& e) {
      j.reason = fmt::format("the fit without seed index {} failed: {}", leave, e.what());
      return j;
    }
  }
  const Eigen::Matrix4d cov = jackknife_covariance(theta);
  j.done = true;
  j.samples = n;
  j.a = std::sqrt(cov(0, 0)), j.b = std::sqrt(cov(1, 1)), j.c = std::sqrt(cov(2, 2)), j.delta = std::sqrt(cov(3, 3));
  j.covariance = cov.topLeftCorner<3, 3>();
  return j;
}

}  // namespace

FitCriteria parse_fit_criteria(const ConfigNode& criteria) {
  const ConfigNode f = criteria.at("fit");
  f.allow_only({"candidates", "judge", "jackknife_relative_max", "chi2_per_dof_max", "runs_z_max"});
  FitCriteria out;
  const ConfigNode cands = f.at("candidates");
  for (const std::string& name : cands.keys()) {
    const ConfigNode c = cands.at(name);
    c.allow_only({"form", "weighting", "onset_force", "sigma_floor"});
    Candidate k{name, {}};
    parse_fit_keys(c, k.options);
    out.candidates.push_back(k);
  }
  if (out.candidates.empty()) cands.fail("no candidate; allowed: at least one");
  const ConfigNode judge = f.at("judge");
  judge.allow_only({"delta_n_max", "sigma_floor"});
  out.delta_n_max = positive_fraction(judge.at("delta_n_max"), 1.0);
  out.sigma_floor = positive_fraction(judge.at("sigma_floor"), 0.5);
  out.jackknife_relative_max = positive_fraction(f.at("jackknife_relative_max"), 10.0);
  out.chi2_per_dof_max = positive_fraction(f.at("chi2_per_dof_max"), 1e6);
  out.runs_z_max = positive_fraction(f.at("runs_z_max"), 100.0);
  for (Candidate& c : out.candidates) {
    c.options.delta_n_max = out.delta_n_max;
    if (c.options.form == FitOptions::Form::clamped) c.options.sigma_floor = out.sigma_floor;
  }
  return out;
}

CandidateFit fit_candidate(const Candidate& c, const SceneCurves& curves, const FitCriteria& criteria) {
  CandidateFit r;
  r.name = c.name;
  r.options = c.options;
  try {
    r.normal = fit_normal_law(curves.delta_n, curves.Fn, curves.Fn_stderr, c.options);
  } catch (const InputError& e) {
    r.reason = e.what();
    return r;
  }
  r.judged = judge_normal_law(*r.normal, curves.delta_n, curves.Fn, curves.Fn_stderr, criteria.sigma_floor,
                              criteria.delta_n_max);
  r.adequate = r.judged.chi2_per_dof <= criteria.chi2_per_dof_max && std::abs(r.judged.runs_z) <= criteria.runs_z_max;
  r.jackknife = jackknife(c.options, curves);
  r.stable = r.jackknife.done && r.jackknife.b <= criteria.jackknife_relative_max * std::abs(r.normal->b) &&
             r.jackknife.delta <= criteria.jackknife_relative_max * std::abs(r.normal->delta);
  if (!curves.kt.empty()) {
    try {
      r.tangential = fit_tangential_law(curves.kt_delta_n, curves.kt, curves.kt_stderr, r.normal->delta, c.options);
    } catch (const InputError& e) {
      r.tangential_reason = e.what();
    }
  } else {
    r.tangential_reason = "no kt averaged";
  }
  return r;
}

Selection select_fit(const std::vector<std::vector<CandidateFit>>& per_scene, const FitCriteria& criteria) {
  Selection s;
  const std::size_t n = criteria.candidates.size();
  for (const auto& scene : per_scene)
    if (scene.size() != n) throw InputError(fmt::format("the fits judge {} candidates; the criteria list {}", scene.size(), n));
  std::vector<bool> stable(n, true), fitted(n, true);
  std::vector<double> worst(n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (const auto& scene : per_scene) {
      const CandidateFit& c = scene[k];
      if (c.name != criteria.candidates[k].name)
        throw InputError(fmt::format("candidate {} is '{}' in a fit file, '{}' in the criteria", k + 1, c.name,
                                     criteria.candidates[k].name));
      fitted[k] = fitted[k] && c.normal && std::isfinite(c.judged.chi2_per_dof);
      stable[k] = stable[k] && c.stable;
      if (c.normal) worst[k] = std::max(worst[k], c.judged.chi2_per_dof);
    }
  for (std::size_t k = 0; k < n; ++k) s.any_stable = s.any_stable || (stable[k] && fitted[k]);
  std::size_t best = n;
  for (std::size_t k = 0; k < n; ++k) {
    if (!fitted[k] || (s.any_stable && !stable[k])) continue;
    if (best == n || worst[k] < worst[best]) best = k;
  }
  if (best == n) {  // reported, not fatal: a profile with too few points for every form still has tables
    s.chosen = n;
    s.why = "none: no candidate could be fitted to every scene";
    return s;
  }
  s.chosen = best;
  s.why = fmt::format("{}: the least worse-scene chi2/dof ({:.3g}) among the {} candidates{}", criteria.candidates[best].name,
                      worst[best], s.any_stable ? "stable" : "fitted",
                      s.any_stable ? fmt::format(" (jackknife error of b and delta <= {:g} of the value in every scene)",
                                                 criteria.jackknife_relative_max)
                                   : " (none is stable: all were considered)");
  return s;
}

}  // namespace softpack::fit
