// The calibration study's report (issue 14, paper/calibration.md): for each setting of a study
// (report/study_file.hpp; experiments/studies/calibrate.yaml) what the measured laws and the packings
// it measures are, each with its seed-to-seed standard error, and how each changes against the
// study's base (its `reference` setting).
//
// Per scene: Eq. 7's δ, a and b, fitted as the setting's profile says (its `fit` section,
// analysis/fit_options.hpp); b of Eq. 7 fitted on the study's fixed range of Δn
// (`calibrate.b_range`, the same for every setting); Fn at the study's Δn (`compare.Fn_delta_n`),
// kt and kt/Fn at its kt Δn; the closed contacts per grain after the first relaxation (Δn = 0)
// and at the first loaded point (Fn above the profile's onset_force × the sweep's largest).
// Per setting: the solid fraction of its packings, and their coordination after growth (contacts
// closed to 1e-9 Rs, grain–grain counted at both grains and grain–shell at the grain, per grain).
//
// Errors: leave-one-seed-out (jackknife) standard errors over the setting's seeds — for a mean the
// usual standard error of the mean, for a fitted coefficient the same carried through the fit.
// A change against the base is unpaired (a setting may change the packings): z = Δ/√(σ² + σ_base²).
#pragma once
#include <string>
#include <vector>

#include "report/study_file.hpp"

namespace softpack {

struct CalibrationRow {
  std::string name, knob;
  std::size_t seeds = 0;
  bool complete = false;     ///< every file is there
  std::string failed;        ///< the first error of its run, when it failed
  double cpu_seconds = 0.0;  ///< of its packings and sweeps
  std::vector<double> value, error;  ///< per quantity (NaN: not measured)
  std::vector<std::string> note;     ///< why a quantity is not measured
};

struct CalibrationReport {
  std::vector<std::string> quantities;
  std::vector<CalibrationRow> rows;  ///< the base (reference) first
};

/// Reads the results under `dir` (<dir>/<setting>/...); settings not complete are listed as such.
CalibrationReport calibration_report(const Study& study, const std::string& dir);

/// table.md, calibration.json and onset.dat (for figures/calibration_onset.gp) in `out_dir`;
/// returns the text of table.md.
std::string write_calibration_report(const CalibrationReport& r, const std::string& out_dir, const std::string& title);

}  // namespace softpack
