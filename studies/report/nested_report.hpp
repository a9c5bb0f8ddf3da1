// The nested soft-particles' report (issue 35, docs/nested.md; a study per level,
// experiments/studies/nested-level-*.yaml, report kind `nested`).
//
// Per setting of the level: its laws as the radius report measures them (Eq. 7, Eq. 8, μ_soft,
// jackknife errors over the seeds; report/radius_report.hpp), written as the law file
// `<setting>/laws.json` at the setting's radius, which the level above reads; its grains and
// sites; and what it cost (the CPU time of its packings and stages).
//
// Every other setting against `nested.against` (the content resolved), by the criterion of the
// criteria file (`nested.criterion` of experiments/nested.yaml, committed before the runs): Fn at
// each normal Δn and kt at each tangential Δn of the grid within the criterion's ranges; a point
// agrees when |mean − mean_against| <= bound √(se² + se_against²); a point is left out when Fn
// (for kt: Fn at its Δn) is below onset_force (Rs / Rs0)² in both settings. The recursion holds
// for a setting when every compared point agrees.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "report/radius_report.hpp"
#include "report/study_file.hpp"

namespace softpack {

struct NestedCriterion {
  std::array<double, 2> Fn_delta_n{}, kt_delta_n{};  ///< [low, high] of the compared Δn
  double bound = 0.0;
  double onset_force = 0.0;  ///< [N] at the radius Rs0
  double Rs0 = 0.0;          ///< nested.packing.Rs: level 0's radius [m]
  /// nested.diagnosis.settings: the settings that each change one rule of the nested form, judged
  /// against the reference as causes of its gap (nested_closer); none where the file has none.
  std::vector<std::string> diagnosis;
};

/// Reads `nested.criterion` and `nested.packing.Rs` of the criteria file; InputError names the key.
NestedCriterion read_nested_criterion(const std::string& path);

struct NestedPoint {
  std::string scene, quantity;  ///< quantity: "Fn" [N] or "kt" [N/m]
  double delta_n = 0.0;
  RadiusValue value, against, ratio;  ///< ratio: value / against, its error propagated
  bool compared = false, agrees = false;
};

struct NestedComparison {
  std::string setting, against;
  std::vector<NestedPoint> points;
  std::size_t compared = 0, agreeing = 0;
  bool holds() const { return compared > 0 && agreeing == compared; }
  /// Against the reference's comparison (a setting that changes one rule of the nested form:
  /// experiments/nested.yaml's diagnosis): of the points compared in both (`closer_of`), those
  /// where this setting's mean is nearer the mean compared against than the reference's is.
  std::size_t closer = 0, closer_of = 0;
  bool cause() const { return closer_of > 0 && closer == closer_of; }  ///< closer at every point
};

struct NestedSetting {
  std::string name, changes;
  double Rs = 0.0;
  bool ran = false;                 ///< has normal results
  std::vector<RadiusRow> rows;      ///< per scene
  double grains = 0.0, sites = 0.0;  ///< of its own level, mean over seeds
  double cpu_packings = 0.0, cpu_stages = 0.0;  ///< [s], summed over seeds and scenes
};

struct NestedReport {
  NestedCriterion criterion;
  std::vector<double> Fn_delta_n;  ///< the normal grid within the criterion's Fn range (the rows' Fn are at these)
  std::vector<NestedSetting> settings;
  std::vector<NestedComparison> comparisons;
};

/// `s` against `against` by the criterion, Fn at `Fn_delta_n` and kt at `kt_delta_n` (the rows'
/// Fn and kt are at these Δn, in this order).
NestedComparison nested_comparison(const NestedSetting& s, const NestedSetting& against, const NestedCriterion& c,
                                   const std::vector<double>& Fn_delta_n, const std::vector<double>& kt_delta_n);

/// The largest Δn of `Fn_delta_n` up to which the row's mean Fn is below the criterion's onset
/// force onset_force (Rs / Rs0)² at every point: the soft-particle carries no force there (a nested
/// content that retreats before it pushes). NaN when it is loaded at the first point.
double nested_unloaded_to(const RadiusRow& row, const std::vector<double>& Fn_delta_n, const NestedCriterion& c, double Rs);

/// Fills `c.closer` and `c.closer_of` against `reference` (both compared with the same setting);
/// nested_report() does so for the criterion's diagnosis settings only.
void nested_closer(NestedComparison& c, const NestedComparison& reference);

/// Reads the runs under `dir` (<dir>/<setting>/...); a setting without normal results is listed as
/// not run. InputError when the criteria file or `nested.against` is missing.
NestedReport nested_report(const Study& study, const std::string& dir);

/// table.md, nested.json and each run setting's laws.json in `out_dir`; returns table.md's text.
std::string write_nested_report(const NestedReport& r, const Study& study, const std::string& out_dir, const std::string& title);

}  // namespace softpack
