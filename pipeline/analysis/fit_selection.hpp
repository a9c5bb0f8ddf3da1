// The preregistered choice of the fit (experiments/criteria.yaml `fit`, paper/preregistration.md):
// each candidate way of fitting Eq. 7 fitted to a scene's averages, judged on the same footing
// (power_fit.hpp: Judgement) and for stability by a leave-one-seed-out jackknife over the
// per-seed curves; then, over both scenes, the rule: the stable candidates (jackknife standard
// error of b and of δ at most jackknife_relative_max of the value, in both scenes; all if none
// is), and among them the least worse-scene χ²/dof. Adequacy (χ²/dof, runs) is reported, not
// chosen on.
#pragma once
#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "analysis/fit_options.hpp"
#include "analysis/power_fit.hpp"
#include "config/yaml_node.hpp"

namespace softpack::fit {

struct Candidate {
  std::string name;
  FitOptions options;
};

struct FitCriteria {
  std::vector<Candidate> candidates;  ///< in the file's order (ties go to the earlier)
  double delta_n_max = 0.5;           ///< judge: every point up to here
  double sigma_floor = 1e-3;          ///< judge: σ >= this × the largest force
  double jackknife_relative_max = 0.25;
  double chi2_per_dof_max = 2.0;
  double runs_z_max = 2.58;
};
/// Reads `fit` of a criteria file (experiments/criteria.yaml); InputError at the key.
FitCriteria parse_fit_criteria(const ConfigNode& criteria);

/// A scene's curves as the fits see them: means, standard errors and (for the jackknife) every
/// seed's values, [point][seed] (empty: no jackknife).
struct SceneCurves {
  std::vector<double> delta_n, Fn, Fn_stderr;
  std::vector<std::vector<double>> Fn_per_seed;
  std::vector<double> kt_delta_n, kt, kt_stderr;
  std::vector<std::vector<double>> kt_per_seed;
};

/// Leave-one-seed-out: each coefficient's jackknife standard error, sqrt((n−1)/n Σ (θ_j − θ̄)²),
/// and the covariance of (a, b, c) likewise (seed_statistics.hpp: jackknife_covariance). Not done
/// (reason) without per-seed values, with fewer than 3 seeds, or when a leave-one-out fit fails.
struct Jackknife {
  bool done = false;
  std::string reason;
  std::size_t samples = 0;
  double a = kNaN, b = kNaN, c = kNaN, delta = kNaN;  ///< standard errors
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Constant(kNaN);
};

/// One candidate fitted to one scene: Eq. 7 and Eq. 8 with its options, judged, jackknifed.
struct CandidateFit {
  std::string name;
  FitOptions options;
  std::optional<PowerLawFit> normal, tangential;
  std::string reason;  ///< why Eq. 7 (or Eq. 8, tangential_reason) could not be fitted
  std::string tangential_reason;
  Judgement judged;
  Jackknife jackknife;
  bool stable = false;  ///< jackknife errors of b and δ within the criterion
  bool adequate = false;
};
CandidateFit fit_candidate(const Candidate& c, const SceneCurves& curves, const FitCriteria& criteria);

/// The rule over both scenes: the index of the chosen candidate (candidates[k] of each scene's
/// list, in the criteria's order), and why, in a sentence; chosen = the number of candidates when
/// none could be fitted to every scene.
struct Selection {
  std::size_t chosen = 0;
  bool any_stable = false;
  std::string why;
};
Selection select_fit(const std::vector<std::vector<CandidateFit>>& per_scene, const FitCriteria& criteria);

}  // namespace softpack::fit
