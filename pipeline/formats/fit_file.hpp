// The fit file of one scene (softpack-fit; read by softpack-table), JSON:
//
//   {"scene": "soft-solid",
//    "normal": {"a", "a_error", "b", "b_error", "c", "c_error", "delta", "delta_error",
//               "points", "weighted", "chi2_per_dof", "range": [dn_min, dn_max],
//               "covariance": [[…]], "notes": […]},
//    "tangential": {the same without delta/delta_error, plus "delta_used"} or null,
//    "tangential_reason": "…" (only when "tangential" is null),
//    "options": {"weighting", "onset_force", "delta_n_max"}   (only when the profile has a `fit` section),
//    "weightings": {"stderr": {"normal", "tangential"}, "unweighted": …, "relative": …}
//                  (only with fit.compare: the same points fitted with each weighting, side by side),
//    "judged": {"chi2_per_dof", "points", "signed_points", "runs", "runs_z"},
//    "jackknife": {"done", "reason", "samples", "a_error", "b_error", "c_error", "delta_error", "covariance"},
//    "candidates": [{"name", "options", "normal", "tangential", "reason", "judged", "jackknife",
//                    "stable", "adequate"}, …]
//                  (the last three since 0.6.0, with --criteria: the profile's fit judged and
//                  jackknifed, and every candidate of experiments/criteria.yaml; analysis/fit_selection.hpp),
//    "errors": "…", "models": {…},
//    "provenance": {"program", "code_version", "inputs": [{"path", "scene", "profile",
//                   "code_version", "seeds"}], "seconds", "cpu_seconds", "stamp"}}
//   (stamp: the average stage's configuration stamp, profile/profile.hpp, with --config; "" without;
//   absent in files from before stamps)
//
// Undefined errors (NaN, e.g. δ's when c >= 0) are written as null. Beside it, on request, the
// coefficients as gnuplot variables for figures/*.gp (a_solid=...; kt_a_solid=...; NaN when
// missing).
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/fit_selection.hpp"
#include "analysis/fit_table.hpp"
#include "analysis/power_fit.hpp"
#include "core/stopwatch.hpp"

namespace softpack {

struct FitFile {
  std::string scene;                           ///< soft-solid or soft-soft
  fit::PowerLawFit normal;                     ///< Eq. 7
  std::optional<fit::PowerLawFit> tangential;  ///< Eq. 8, or none with the reason:
  std::string tangential_reason;
  std::optional<fit::FitOptions> options;  ///< the profile's `fit` section, when it has one
  struct Alternative {                     ///< the fit with another weighting (fit.compare)
    std::string weighting;
    std::optional<fit::PowerLawFit> normal, tangential;
    std::string reason;  ///< why a law could not be fitted
  };
  std::vector<Alternative> weightings;
  std::optional<fit::Judgement> judged;     ///< the profile's Eq. 7 fit judged (--criteria)
  std::optional<fit::Jackknife> jackknife;  ///< and jackknifed over the seeds (--criteria)
  std::vector<fit::CandidateFit> candidates;  ///< every candidate of the criteria (--criteria)
  struct Input {  ///< the average file fitted (formats/average_file.hpp)
    std::string path, profile, code_version;
    std::int64_t seeds = 0;
  } input;
  std::string code_version;
  double seconds = 0.0;      ///< wall-clock time [s]
  double cpu_seconds = 0.0;  ///< CPU time of the process [s]
  std::string stamp;         ///< the average stage's stamp of the profile (--config; "" without)
};

/// The JSON text of the file (what write_fit_file writes).
std::string fit_file_text(const FitFile& f);
/// Writes the fit file atomically.
void write_fit_file(const std::string& path, const FitFile& f);
/// Writes the gnuplot variables file atomically.
void write_fit_gnuplot_file(const std::string& path, const FitFile& f);

/// What softpack-table reads from a fit file: {key: value ± error} of each law (a null error
/// is NaN).
struct FitEstimates {
  std::string scene;
  std::map<std::string, table::Estimate> normal;                     ///< a, b, c, delta
  std::optional<std::map<std::string, table::Estimate>> tangential;  ///< a, b, c; none when null
  std::string code_version = "?";                                    ///< of softpack-fit ("?": not said)
  std::string stamp;                                                 ///< the average stage's ("": not said)
  std::optional<Elapsed> time;  ///< of softpack-fit (provenance seconds, cpu_seconds), when the file says
  std::optional<fit::Judgement> judged;      ///< of the profile's fit (files since 0.6.0 made with --criteria)
  std::optional<fit::Jackknife> jackknife;   ///< of the profile's fit (idem)
  /// The candidates (idem): name, normal and tangential (coefficients, errors, δ; no notes),
  /// judged, jackknife, stable, adequate.
  std::vector<fit::CandidateFit> candidates;
};
/// InputError naming the file and the key: not JSON, no scene, a missing or non-numeric
/// coefficient, an error that is neither a number nor null.
FitEstimates read_fit_file(const std::string& path);

}  // namespace softpack
