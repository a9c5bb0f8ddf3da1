// The fidelity study's comparison (docs/accuracy.md): for each setting of the study
// (report/study_file.hpp) the quantities a user takes from a measurement — a, b, c, δ of
// Eq. 7 and a, b, c of Eq. 8 for both scenes, Fn at the study's Δn and kt at its Δn — from its
// sweep results (averaged over its seeds and fitted here, as softpack-average and softpack-fit
// do), their error against the reference in units of the reference's seed-to-seed standard
// error, and the CPU time the setting's outputs record (report/stage_timing.hpp).
//
// Error of a setting that runs: paired, against the reference on the same seeds — the same
// soft-particles, so the difference is the knob's alone; soft-soft pairs two packings (the
// workflow's rule, read from each results file's provenance), and only the pairs both runs made
// are compared. A setting `of`
// another with fewer seeds is compared with the reference on all its seeds (the error of
// fewer seeds is their sampling error). The unit σ of each quantity is the reference's
// leave-one-seed-out (jackknife) standard error over all its seeds (for a mean it is the usual
// standard error of the mean, for a fitted coefficient the same idea carried through the fit),
// at least the reference's own standard error. Quantities the reference does not establish (not
// measured, or within 2 σ of zero) are left out of a setting's largest and rms error.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "report/study_file.hpp"

namespace softpack {

/// One measured quantity: "soft-solid normal a", "soft-soft Fn(0.5)", ... NaN where it could
/// not be measured (a fit that failed: `note` says why).
struct Quantity {
  std::string name;
  double value = 0.0;
  double error = 0.0;  ///< its own standard error: of the mean over the seeds, or of the fit
  std::string note;
};

struct SettingRow {
  std::string name;
  std::string knob;           ///< the keys it changes ("(the paper's protocol)" for none)
  bool runs = true;
  std::size_t seeds = 0;
  double cpu_seconds = 0.0;   ///< of its measurement: packings and sweeps of its seeds
  bool complete = false;      ///< every file is there
  std::string failed;         ///< the first error of its run, when it failed (DATA/accuracy/<setting>/failed.txt)
  std::vector<double> z;      ///< error / σ per quantity (NaN: not measured)
  double max_z = 0.0, rms_z = 0.0;
  std::string worst;          ///< the quantity of max_z
  double residual = 0.0;      ///< median final force ratio over its loaded normal points
  bool pareto = false;        ///< no other setting is both cheaper and more accurate
};

struct AccuracyReport {
  std::vector<std::string> quantities;
  std::vector<double> reference_value, reference_sigma;  ///< over all the reference's seeds
  std::vector<bool> established;  ///< the reference measures it and tells it from zero (2 σ)
  double reference_cpu = 0.0;
  std::vector<SettingRow> rows;
};

/// Reads the sweep results under `dir` (<dir>/<setting>/{normal,tangential,packings}/...).
/// Settings whose files are missing are reported as incomplete, not refused.
AccuracyReport accuracy_report(const Study& study, const std::string& dir);

/// table.md (the summary and the error of every quantity), pareto.dat (for gnuplot), report.json;
/// returns the text of table.md.
std::string write_accuracy_report(const AccuracyReport& r, const std::string& out_dir, const std::string& title);

}  // namespace softpack
