// The radius study's report (issue 16, docs/radius.md; experiments/studies/radius.yaml): how the
// soft-particle's laws change with its shell radius Rs, its friction coefficient, the contact of
// two radii, and the law file a simulation reads (formats/law_file.hpp).
//
// Per setting and scene: Eq. 7 (δ, a, b, c) and Eq. 8 (a, b; kt in N per metre of ht) fitted as
// the setting's profile says; Fn and kt at the study's Δn; the friction coefficient
// μ_soft = Ft / Fn in the contact's frame (turned by the orbit's angle for soft-soft), averaged
// over the sliding points with ht / Rs >= radius.mu_from_ht_over_Rs, per sliding Δn. Errors:
// seed-to-seed — the standard error of the mean, and for a fit the jackknife (leave one seed out).
//
// Scaling, per variant (self-similar, fixed) and scene: X(R) = X(R0) (R / R0)^n for Fn at each
// compared Δn (one n shared by all Δn: a weighted least-squares line through log X per Δn with a
// common slope), for kt likewise, and for Eq. 7's a alone; n's error from the fit, times
// √(χ²/dof) when the points scatter more than their errors. Hertz's law makes n = 2 for Fn and
// 1 for kt exact for self-similar soft-particles in the quasi-static limit.
//
// Mixed radii: the soft-soft force of radii R1 = Rs, R2 = k Rs against the reduced-radius rule
// of solid spheres: the equal-size soft-soft law at R_eq = 2 R1 R2 / (R1 + R2) (the same R12),
// Fn(hn) = (R_eq / R0)² Fn_R0(hn / R_eq), interpolated on the reference's grid; and the same
// with R_eq = R1 and R_eq = R2 for comparison.
#pragma once
#include <string>
#include <vector>

#include "formats/law_file.hpp"
#include "formats/sweep_file.hpp"
#include "report/study_file.hpp"

namespace softpack {

struct RadiusValue {
  double value = 0.0, error = 0.0;
};

/// One setting's laws for one scene.
struct RadiusRow {
  std::string setting, scene;
  double Rs = 0.0, r_max = 0.0, grains = 0.0;
  std::size_t seeds = 0;
  RadiusValue delta, a, b, c;         ///< Eq. 7 (a, c in N)
  RadiusValue kt_a, kt_b;             ///< Eq. 8 (a in N/m)
  double dn_min = 0.0, dn_max = 0.0;  ///< the Δn range Eq. 7 was fitted on
  double kt_dn_min = 0.0, kt_dn_max = 0.0;  ///< and Eq. 8
  std::vector<RadiusValue> Fn, kt;    ///< at the study's compare Δn
  std::vector<double> mu_delta_n;     ///< the sliding Δn
  std::vector<RadiusValue> mu, mu_peak;  ///< μ_soft on the plateau, and the largest Ft / Fn
  std::string note;                   ///< what could not be measured
};

/// A scaling exponent of one quantity for one variant and scene.
struct RadiusScalingRow {
  std::string variant, scene, quantity;  ///< quantity: "Fn", "kt", "a"
  RadiusValue exponent;
  double chi2_per_dof = 0.0, R_min = 0.0, R_max = 0.0;
  std::size_t radii = 0;
};

/// The mixed contact against each rule: the mean over the loaded points of measured / predicted − 1.
struct MixedRow {
  std::string setting;
  double ratio = 0.0;  ///< R2 / R1
  std::vector<std::string> rules;
  std::vector<RadiusValue> deviation;
  std::vector<double> delta_n, measured, predicted;  ///< per loaded point, the reduced-radius rule
};

struct RadiusReport {
  std::vector<double> Fn_delta_n, kt_delta_n;
  double R0 = 0.0;
  std::vector<RadiusRow> rows;
  std::vector<RadiusScalingRow> scaling;
  std::vector<MixedRow> mixed;
  std::vector<std::string> missing;  ///< settings without normal results (a setting with some is reported, noted)
};

/// Reads the results under `dir` (<dir>/<setting>/...): a setting is reported from the stages it
/// has run (normal first; what is missing is noted), one without normal results is listed as
/// missing. InputError when the reference lacks a stage.
RadiusReport radius_report(const Study& study, const std::string& dir);

/// A common slope n of log y against log x over several groups (one intercept each), weighted by
/// 1/σ_log²: the exponent of a power law measured at several Δn. Exposed for the tests.
RadiusValue common_exponent(const std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& y,
                            const std::vector<std::vector<double>>& y_error, double* chi2_per_dof = nullptr);

/// μ_soft per sliding Δn into `row` (mu_delta_n, mu, mu_peak, note): Ft / Fn in the contact's
/// frame averaged over the points with ht / Rs >= `from`, then over the seeds whose contact carries
/// a normal force at every sliding point of that Δn — when at least `least` seeds do (0: every
/// seed must; the study's nested.mu_seeds_loaded), else NaN with a note. Exposed for the tests.
void sliding_friction(const std::vector<SweepResults>& sliding, const std::vector<double>& sliding_delta_n, double Rs, double from,
                      std::size_t least, RadiusRow& row);

/// One setting's laws, scene by scene, measured as the rows of the radius report are (the fits
/// with their jackknife errors, Fn and kt at the study's compare Δn, μ_soft from the sliding
/// stage); none when the setting has no normal results yet. Its shell radius in `Rs`.
std::vector<RadiusRow> setting_law_rows(const Study& study, const std::string& dir, const std::string& setting, double* Rs = nullptr);

/// A scene's laws in the law file's terms: Eq. 7, Eq. 8 (c = −a δ^b) and μ_soft of a row.
SceneLaws row_scene_laws(const RadiusRow& row);

/// The law file of the study's reference (its laws at R0, the scaling of the fixed variant, or
/// the self-similar one without it, and the mixing rule's check).
LawFile radius_law_file(const RadiusReport& r, const Study& study, const std::string& code_version);

/// table.md, radius.json, scaling.dat and friction.dat (figures/radius_*.gp) and laws.json in
/// `out_dir`; returns the text of table.md.
std::string write_radius_report(const RadiusReport& r, const Study& study, const std::string& out_dir,
                                const std::string& title);

}  // namespace softpack
